# Tests of bench/: the benchmark programs run the instruction set the shadowlab executable would take
# (bench/isa_main.cpp), each set they hold gives the same depth maps, and a bad SHADOWLAB_ISA is refused
# (bench.isa_dispatch); --runs lists every run of every case and refuses bad counts (bench.runs). Scripts run by
# ctest (the programs are executables of their own), where the benchmarks are built.
if(SHADOWLAB_BENCH)
  add_test(NAME bench.isa_dispatch
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/bench/isa_dispatch_test.sh $<TARGET_FILE:shadowlab_bench_depth>
                   $<TARGET_FILE:shadowlab_bench_pcf> $<TARGET_FILE:shadowlab> "${SHADOWLAB_ISAS}")
  set_tests_properties(bench.isa_dispatch PROPERTIES TIMEOUT 300)
  add_test(NAME bench.runs
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/bench/runs_test.sh $<TARGET_FILE:shadowlab_bench_depth>
                   $<TARGET_FILE:shadowlab_bench_pcf>)
  set_tests_properties(bench.runs PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)
endif()
