#!/usr/bin/env bash
# Installs pistondyn's build dependencies from Debian 12 packages, only those missing.
# Runs as root, or through sudo where not root.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libsimbody-dev          # multibody engine (3.7)
  libeigen3-dev           # dense/sparse linear algebra for the numerics
  libsuitesparse-dev      # CHOLMOD / UMFPACK / KLU sparse direct solvers
  libyaml-cpp-dev         # YAML engine decks (pistondyn::io)
  nlohmann-json3-dev      # summary.json (pistondyn::io, header-only, build time)
  libcli11-dev            # command line of the pistondyn program (app/, header-only)
  libspdlog-dev           # the program's log (app/, --log-level)
  gnuplot-nox             # figures: pistondyn plot / report / run (pngcairo, no X)
  chromium                # tests: report.html rendered headless (skipped without it)
  libgtest-dev googletest # test suite
  libbenchmark-dev        # bench/
  libopenmpi-dev openmpi-bin  # optional: `mpirun -np K pistondyn sweep` (PISTONDYN_WITH_MPI)
  libnlopt-cxx-dev        # the design loop's optimiser (pistondyn::design; NLopt 2.7)
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest  # the Python module
  clang libclang-rt-14-dev llvm  # .ci: sanitizer suite, libFuzzer targets, symbolised stacks
)

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
