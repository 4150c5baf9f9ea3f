#!/usr/bin/env bash
# Shared by scripts/run_experiment and scripts/test: installs missing Debian
# packages (scripts/setup.sh), then configures and builds Release into build/
# incrementally. Progress goes to stderr so stdout stays clean for the command.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

bash "$ROOT/scripts/setup.sh" >&2
if [ ! -f "$ROOT/build/CMakeCache.txt" ]; then
  cmake -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE=Release >&2
fi
JOBS="${CORRMP_JOBS:-$(nproc)}"
cmake --build "$ROOT/build" --parallel "$JOBS" >&2
