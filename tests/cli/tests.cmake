# End-to-end tests of the shadowlab executable (tests/cli/): they run the built binary, whose path reaches them
# as SHADOWLAB_CLI. tests/CMakeLists.txt applies SHADOWLAB_TEST_DEFINITIONS and makes the tests depend on it.
if(TARGET shadowlab)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/projective_cli_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/eval_cli_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/filtered_cli_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/eval_html_browser_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_scripting_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/full_disk_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/kill_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/material_cli_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/look_cli_test.cpp)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/isa_dispatch_test.cpp)
  list(APPEND SHADOWLAB_TEST_DEFINITIONS SHADOWLAB_CLI="$<TARGET_FILE:shadowlab>")
  # The instruction sets the executable holds, comma-separated (isa_dispatch_test.cpp compares them).
  string(REPLACE ";" "," _isas "${SHADOWLAB_ISAS}")
  list(APPEND SHADOWLAB_TEST_DEFINITIONS SHADOWLAB_BUILT_ISAS="${_isas}")
  find_package(nlohmann_json CONFIG REQUIRED)
  # valijson (Debian libvalijson-dev, header-only) checks the --json documents against docs/cli/*.schema.json.
  find_package(valijson CONFIG REQUIRED)
  list(APPEND SHADOWLAB_TEST_LIBS shadowlab::io shadowlab::scenes nlohmann_json::nlohmann_json valijson
       OpenImageIO::OpenImageIO)
endif()
