#!/usr/bin/env bash
# Installs the dependencies, configures and builds everything (Release, in build/), and runs
# the test suite without the long studies (label `study`; run those with ctest -L study).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j2
ctest --test-dir build --output-on-failure -LE study -j2
