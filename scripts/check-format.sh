#!/usr/bin/env bash
# Fails when a C++ file of the project differs from .clang-format; prints the files to fix.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bad=0
while IFS= read -r -d '' f; do
  if ! clang-format --style=file "$f" | cmp -s - "$f"; then
    echo "format: $f differs from .clang-format (run: clang-format -i $f)"
    bad=1
  fi
done < <(git ls-files -z -- '*.h' '*.hpp' '*.cpp' 2>/dev/null || find . -path ./build -prune -o \( -name '*.h' -o -name '*.cpp' \) -print0)
if ((bad)); then exit 1; fi
echo "format: ok"
