#!/usr/bin/env bash
# Builds Inertia Lab for the browser: a static folder (index.html, the JS glue, the .wasm, the
# worker's script) that any static server serves, e.g. `python3 -m http.server -d target/web 8000`.
#
#   web/build.sh [OUT]      build into OUT (default target/web); with INERTIA_LAB_URL set (the
#                           project's home page), the page links to its "the-app" section
#   web/build.sh --single-file [OUT.html]
#                           the same page as one HTML file (default target/inertia-lab.html) that
#                           runs from the disk with no server: the module and the worker inline
#   web/build.sh --check    only check the toolchain (exit 3 and the install line when missing)
#   web/build.sh --clippy   lint the code the web build compiles (the platform modules' web sides
#                           are seen by no desktop build), with warnings as errors
#
# rustup's toolchains here have no wasm32 standard library; Debian's rustc-web does, and builds
# one from its source (-Zbuild-std). See shared/notes/web.md.
set -euo pipefail
cd "$(dirname "$0")/.."

RUSTC_WEB=/usr/bin/rustc
CARGO_WEB=/usr/bin/cargo
STD_SOURCE=/usr/lib/rustlib/src/rust/library
WASM_LD=/usr/lib/llvm-22/bin/wasm-ld
# The glue generator must be the version of the wasm-bindgen crate in Cargo.lock.
BINDGEN_VERSION=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
INSTALL="apt-get install rustc-web cargo-web rust-web-src rust-web-clippy lld-22 binaryen && cargo install wasm-bindgen-cli --version =$BINDGEN_VERSION"

missing=()
{ [[ -x $RUSTC_WEB ]] && [[ -x $CARGO_WEB ]]; } || missing+=("Debian's rustc-web and cargo-web")
[[ -d $STD_SOURCE ]] || missing+=("the standard library's source (rust-web-src)")
[[ -x $WASM_LD ]] || missing+=("wasm-ld (lld-22)")
command -v wasm-opt >/dev/null || missing+=("wasm-opt (binaryen)")
if ! command -v wasm-bindgen >/dev/null; then
  missing+=("wasm-bindgen-cli $BINDGEN_VERSION")
elif [[ $(wasm-bindgen --version) != "wasm-bindgen $BINDGEN_VERSION" ]]; then
  missing+=("wasm-bindgen-cli $BINDGEN_VERSION (found $(wasm-bindgen --version))")
fi
if ((${#missing[@]})); then
  echo "web/build.sh: missing: $(printf '%s; ' "${missing[@]}")" >&2
  echo "web/build.sh: install with: $INSTALL" >&2
  exit 3
fi
[[ ${1:-} == --check ]] && exit 0
if [[ ${1:-} == --clippy ]]; then
  [[ -x /usr/bin/cargo-clippy ]] || { echo "web/build.sh: missing: Debian's rust-web-clippy" >&2; echo "web/build.sh: install with: $INSTALL" >&2; exit 3; }
  # Debian's cargo-clippy, not rustup's, which comes first on PATH. In the build's own folder
  # and profile, so that the build after it finds the host's proc-macros and build scripts made.
  PATH=/usr/bin:$PATH RUSTC=$RUSTC_WEB RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR=target/wasm \
    "$CARGO_WEB" clippy --locked --release -p inertia-lab-web -p inertia-lab --lib \
    --target wasm32-unknown-unknown -Zbuild-std=std,panic_abort -- -D warnings
  exit
fi

SINGLE_FILE=
if [[ ${1:-} == --single-file ]]; then
  SINGLE_FILE=${2:-target/inertia-lab.html}
  set -- target/web-single
fi
OUT=${1:-target/web}
# A target folder of its own: another compiler, and Cargo holds the workspace's locked while
# its tests run (the browser test calls this script).
WASM_TARGET=target/wasm
RUSTC=$RUSTC_WEB RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR=$WASM_TARGET \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=$WASM_LD \
  "$CARGO_WEB" build --locked --release -p inertia-lab-web --target wasm32-unknown-unknown \
  -Zbuild-std=std,panic_abort

BUILT=$WASM_TARGET/wasm32-unknown-unknown/release/inertia_lab_web.wasm
OPTIMISED=$WASM_TARGET/optimised
mkdir -p "$OPTIMISED" "$OUT"
# Before wasm-bindgen, never after: Debian's binaryen rewrites the externref table that
# wasm-bindgen's output relies on (shared/notes/web.md).
wasm-opt -O2 "$BUILT" -o "$OPTIMISED/inertia_lab_web.wasm"
wasm-bindgen --target web --no-typescript --out-dir "$OUT" "$OPTIMISED/inertia_lab_web.wasm"
cp web/worker.js "$OUT/"
# The page links to the project's home only when one is configured: a made-up address would be a
# dead link in every copy of the page.
if [[ -n ${INERTIA_LAB_URL:-} ]]; then
  sed "s|@INERTIA_LAB_URL@|${INERTIA_LAB_URL//|/\\|}|" web/index.html >"$OUT/index.html"
else
  grep -v '@INERTIA_LAB_URL@\|INERTIA_LAB_URL)' web/index.html >"$OUT/index.html"
fi
if [[ -n $SINGLE_FILE ]]; then
  python3 web/single_file.py "$OUT" "$SINGLE_FILE"
  echo "web/build.sh: built $SINGLE_FILE ($(du -h "$SINGLE_FILE" | cut -f1)), which runs from the disk"
  exit
fi
echo "web/build.sh: built $OUT:"
ls -l "$OUT"
