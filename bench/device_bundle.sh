#!/bin/sh
# Packs the benchmark programs with every shared library they load and Mesa's llvmpipe (EGL surfaceless) into
# one folder, to measure shadowlab beside llvmpipe on another x86-64 Linux machine that has none of them (only a
# glibc at least as new as this machine's). Run it here after a Release build:
#   bench/device_bundle.sh [BUILD_DIR] [BUNDLE_DIR]     (defaults: build, .bundle in the repository)
# and on the target machine:
#   sh BUNDLE_DIR/run.sh [OUT_DIR]                      (default: $OUT, else BUNDLE_DIR/out)
# BUNDLE_DIR then holds shadowlab-bundle.tar.xz (the programs, libraries, llvmpipe and the dragon asset), run.sh,
# and xz/ (an xz decompressor with its liblzma, used when the target has no xz). run.sh unpacks into a fresh
# /tmp folder, points the dynamic loader, libglvnd and Mesa's loader at the bundle only (so a vendor driver
# there, NVIDIA's for instance, is never used), and runs --verify and the --scaling benchmarks.
# The build's tests/shadowlab_tests comes along where it exists (run.sh: TESTS=<gtest filter>).
# Set BUNDLE_TEST=1 to unpack and smoke-test the bundle here in a clean environment with the system's copies
# of the bundled libraries hidden (needs root for a private mount namespace; skipped otherwise).
set -eu

repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
dest=${2:-$repo/.bundle}
mesa_dri=${MESA_DRI_DIR:-/usr/lib/x86_64-linux-gnu/dri}
egl_json=${MESA_EGL_JSON:-/usr/share/glvnd/egl_vendor.d/50_mesa.json}
assets=${SHADOWLAB_ASSETS:-$repo/../shared/assets}

for b in shadowlab_bench_depth shadowlab_bench_pcf; do
  [ -x "$build/bench/$b" ] || { echo "device_bundle: $build/bench/$b missing (build the bench targets)" >&2; exit 1; }
done
[ -f "$mesa_dri/swrast_dri.so" ] || { echo "device_bundle: no $mesa_dri/swrast_dri.so (libgl1-mesa-dri)" >&2; exit 1; }
egl_mesa=$(sed -n 's/.*"library_path" *: *"\([^"]*\)".*/\1/p' "$egl_json")
egl_mesa_path=$(ldconfig -p | awk -v n="$egl_mesa" '$1 == n && /x86-64/ {print $NF; exit}')
[ -n "$egl_mesa_path" ] || { echo "device_bundle: $egl_mesa (from $egl_json) not found" >&2; exit 1; }

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
root=$stage/shadowlab-bundle
mkdir -p "$root/bin" "$root/lib" "$root/dri" "$root/egl" "$root/assets/stanford_dragon"
cp "$build/bench/shadowlab_bench_depth" "$build/bench/shadowlab_bench_pcf" "$root/bin/"
# The build's test program too, where it has one (a build for another instruction set, e.g. configured with
# -DSHADOWLAB_ISAS=avx512 -DSHADOWLAB_TEST_MODULES='raster;raster/reference', whose tests this machine cannot run):
# run.sh runs it with TESTS=<gtest filter>.
[ -x "$build/tests/shadowlab_tests" ] && cp "$build/tests/shadowlab_tests" "$root/bin/"
cp -L "$mesa_dri/swrast_dri.so" "$root/dri/"
cp -L "$egl_mesa_path" "$root/lib/$egl_mesa"
if [ -f "$assets/stanford_dragon/dragon_vrip.glb" ]; then
  cp "$assets/stanford_dragon/dragon_vrip.glb" "$root/assets/stanford_dragon/"
else
  echo "device_bundle: $assets/stanford_dragon/dragon_vrip.glb not found: case (c) will be skipped there" >&2
fi

# Every library the programs, the EGL vendor library and the DRI driver load (ldd resolves the whole tree),
# except glibc's own (the target's glibc is at least as new) and the loader. The EGL and GL entry points
# (libglvnd's libEGL, libOpenGL, libGLdispatch) come along as ldd finds them.
is_glibc() {
  case "$1" in
    linux-vdso.so.*|ld-linux*|libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|libresolv.so.*|\
    libutil.so.*|libanl.so.*|libmvec.so.*|libnsl.so.*|libBrokenLocale.so.*|libthread_db.so.*) return 0 ;;
  esac
  return 1
}
for f in "$root"/bin/* "$root/lib/$egl_mesa" "$root/dri/swrast_dri.so"; do
  ldd "$f" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}'
done | sort -u | while read -r name path; do
  is_glibc "$name" || cp -L "$path" "$root/lib/$name"
done
# Mesa opens libglapi (shared dispatch) and libgbm through the DT_NEEDED of its own libraries: ldd above has them.
for need in libglapi.so.0 libEGL.so.1 libGLdispatch.so.0 libLLVM-15.so.1; do
  [ -f "$root/lib/$need" ] || echo "device_bundle: warning: $need is not in the bundle" >&2
done

cat > "$root/egl/50_mesa.json.in" <<'EOF'
{
    "file_format_version" : "1.0.0",
    "ICD" : {
        "library_path" : "@LIB@/EGL_MESA"
    }
}
EOF
sed -i "s|EGL_MESA|$egl_mesa|" "$root/egl/50_mesa.json.in"
{
  echo "built $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -n)"
  echo "commit $(git -C "$repo" rev-parse HEAD 2>/dev/null || echo unknown)"
  ldd --version | head -1
  echo "mesa $(dpkg-query -W -f '${Version}' libgl1-mesa-dri 2>/dev/null || echo unknown)"
} > "$root/BUILD_INFO"

mkdir -p "$dest"
rm -f "$dest/shadowlab-bundle.tar.xz"
echo "device_bundle: compressing $(du -sh "$root" | cut -f1) (xz, a few minutes)" >&2
tar -C "$stage" -cf - shadowlab-bundle | xz "-${XZ_LEVEL:-6}" -T0 > "$dest/shadowlab-bundle.tar.xz"
# An xz for targets without one: the binary and its liblzma (glibc comes from the target).
mkdir -p "$dest/xz"
cp -L "$(command -v xz)" "$dest/xz/xz"
ldd "$dest/xz/xz" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | while read -r name path; do
  is_glibc "$name" || cp -L "$path" "$dest/xz/$name"
done
cp "$repo/bench/device_run.sh" "$dest/run.sh"
size=$(wc -c < "$dest/shadowlab-bundle.tar.xz")
echo "device_bundle: $dest/shadowlab-bundle.tar.xz, $size bytes ($((size / 1048576)) MiB)" >&2
[ "$size" -le $((60 * 1048576)) ] || echo "device_bundle: warning: over 60 MiB" >&2

if [ "${BUNDLE_TEST:-0}" = 1 ]; then
  # Hide the system's copy of every bundled library (and its Mesa driver folder and vendor files) in a private
  # mount namespace, then run the bundle's smoke test with an empty environment.
  hide=$(mktemp)
  for f in "$stage"/shadowlab-bundle/lib/*; do
    n=$(basename "$f")
    for d in /lib/x86_64-linux-gnu /usr/lib/x86_64-linux-gnu; do [ -e "$d/$n" ] && echo "$d/$n"; done
  done | sort -u > "$hide"
  out=$(mktemp -d)
  unshare -m --propagation private sh -c '
    set -e
    empty=$(mktemp -d)
    while read -r f; do mount --bind /dev/null "$f"; done < "$1"
    mount --bind "$empty" "$2"
    mount --bind "$empty" /usr/share/glvnd
    env -i PATH=/usr/bin:/bin SMOKE=1 sh "$3/run.sh" "$4"
  ' sh "$hide" "$mesa_dri" "$dest" "$out"
  echo "device_bundle: smoke test output in $out" >&2
  rm -f "$hide"
fi
