#!/usr/bin/env bash
# README command (a): install dependencies, build, run the main example engine.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
./build/app/pistondyn run examples/engines/gasoline_1400_2000rpm/engine.yaml \
  --out results/gasoline_1400_2000rpm
