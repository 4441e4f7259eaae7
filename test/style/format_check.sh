#!/usr/bin/env bash
# Every C++ file in the repository is written in the style of its .clang-format: clang-format
# (Debian's) would change nothing. Lists the files it would change and fails if there are any.
set -euo pipefail
cd "$1"
if [ -d .git ] || [ -f .git ]; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find lib drivers test bench -name '*.cpp' -o -name '*.hpp' -o -name '*.h')
fi
# One clang-format over all files; each file it would change is named in its diagnostics.
mapfile -t unformatted < <(clang-format --dry-run "${files[@]}" 2>&1 |
  sed -nE 's/^([^:]+):[0-9]+:[0-9]+: (warning|error): code should be clang-formatted.*/\1/p' |
  sort -u)
if [ ${#unformatted[@]} -ne 0 ]; then
  echo "format_check: ${#unformatted[@]} of ${#files[@]} files differ from .clang-format:"
  printf '  %s\n' "${unformatted[@]}"
  echo "format_check: fix with: clang-format -i <file>"
  exit 1
fi
echo "format_check: ${#files[@]} files match .clang-format"
