#!/usr/bin/env bash
# Lays out every C++ file of sdk/, tiers/, backends/, tools/, samples/ and tests/ with
# .clang-format, in place (tests/check_format.sh checks the result).
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format=$(command -v clang-format-14 || command -v clang-format)
git ls-files 'sdk/*.cpp' 'sdk/*.hpp' 'tiers/*.cpp' 'tiers/*.hpp' 'backends/*.cpp' 'backends/*.hpp' \
  'tools/*.cpp' 'tools/*.hpp' 'samples/*.cpp' 'samples/*.hpp' 'tests/*.cpp' 'tests/*.hpp' | xargs "$clang_format" --style=file -i
