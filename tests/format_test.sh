#!/usr/bin/env bash
# Every C++ source of the repository is clang-format clean (.clang-format at the root).
# Usage: format_test.sh CLANG_FORMAT SOURCE_DIR. Fix a failure with:
#   git ls-files '*.cpp' '*.h' | xargs clang-format -i
set -euo pipefail
clang_format=$1
cd "$2"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.h' |
    while read -r f; do [[ -e $f ]] && echo "$f"; done)
else
  mapfile -t files < <(find . -path ./build\* -prune -o \( -name '*.cpp' -o -name '*.h' \) -print)
fi
bad=0
for f in "${files[@]}"; do
  if ! "$clang_format" --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not clang-format clean: $f"
    bad=$((bad + 1))
  fi
done
echo "format: ${#files[@]} files checked, $bad not clean"
((bad == 0))
