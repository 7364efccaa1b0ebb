#!/usr/bin/env bash
# Every test: installs what is missing, builds, and runs the unit, CLI, round-trip, codegen,
# plugin and conformance tests with ctest. Tests that need ../shared skip when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
