#!/usr/bin/env bash
# Fails if a C++ file in the tree is not clang-formatted (style in .clang-format).
set -euo pipefail
cd "$(dirname "$0")/.."
files=$(git ls-files '*.hpp' '*.cpp' '*.h' '*.cc')
clang-format --dry-run -Werror $files
echo "format: $(echo "$files" | wc -l) files clang-formatted"
