#!/usr/bin/env bash
# README command (a): install what the program needs, build the program alone (not the
# tests, fuzzers or benchmarks: `scripts/test.sh` builds those later in the same build/),
# run the main example engine at preview fidelity (--fidelity full: the deck's own grid).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh --main
# The same configuration as scripts/test.sh, so that it reuses this build folder.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target pistondyn_exe
./build/app/pistondyn run examples/engines/gasoline_1400_2000rpm/engine.yaml \
  --out results/gasoline_1400_2000rpm --fidelity preview
echo "quickstart: the figures are in results/gasoline_1400_2000rpm/plots/;" \
  "./build/app/pistondyn report results/gasoline_1400_2000rpm writes report.html;" \
  "add --fidelity full for the deck's own film grid; ./scripts/test.sh builds and runs the tests"
