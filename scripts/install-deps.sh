#!/usr/bin/env bash
# Installs pistondyn's build dependencies from Debian 12 packages, only those missing.
# Runs as root, or through sudo where not root.
#
#   install-deps.sh          everything: the program, the tests, benchmarks, MPI sweeps, CI
#   install-deps.sh --main   what configuring the build and running the program need (the
#                            quick start): no Chromium, MPI, clang or LLVM; a later call
#                            without --main adds them to the same machine
set -euo pipefail

# Configure (tests and benchmarks are configured even when not built), build and run.
MAIN_PACKAGES=(
  build-essential cmake pkg-config
  libsimbody-dev          # multibody engine (3.7)
  libeigen3-dev           # dense/sparse linear algebra for the numerics
  libsuitesparse-dev      # CHOLMOD / UMFPACK / KLU sparse direct solvers
  libyaml-cpp-dev         # YAML engine decks (pistondyn::io)
  nlohmann-json3-dev      # summary.json (pistondyn::io, header-only, build time)
  libcli11-dev            # command line of the pistondyn program (app/, header-only)
  libspdlog-dev           # the program's log (app/, --log-level)
  gnuplot-nox             # figures: pistondyn plot / report / run (pngcairo, no X)
  libgtest-dev googletest # test suite (found at configure time)
  libbenchmark-dev        # bench/ (found at configure time)
)
# The rest of the test suite and CI.
MORE_PACKAGES=(
  chromium                # tests: report.html rendered headless (skipped without it)
  doxygen graphviz        # API reference: cmake --build build --target docs, ctest -L docs
  libopenmpi-dev openmpi-bin  # optional: `mpirun -np K pistondyn sweep` (PISTONDYN_WITH_MPI)
  libnlopt-cxx-dev        # the design loop's optimiser (pistondyn::design; NLopt 2.7)
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest  # the Python module
  clang libclang-rt-14-dev llvm  # .ci: sanitizer suite, libFuzzer targets, symbolised stacks
)

PACKAGES=("${MAIN_PACKAGES[@]}")
case "${1:-}" in
  --main) ;;
  "") PACKAGES+=("${MORE_PACKAGES[@]}") ;;
  *) echo "usage: install-deps.sh [--main]" >&2; exit 2 ;;
esac

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
