#!/usr/bin/env bash
# Formats every C++ file of the repository with clang-format and the repository's .clang-format.
# Usage: scripts/format.sh           rewrite the files in place
#        scripts/format.sh --check   change nothing; list the files that need formatting, exit 1 if any
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$VISP_SSL_ROOT"

check=0
case "${1:-}" in
"") ;;
--check) check=1 ;;
-h | --help)
  sed -n '2,4p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
  ;;
*)
  echo "format.sh: unknown option '$1' (see --help)" >&2
  exit 2
  ;;
esac

# Tracked files plus new ones not yet added (but not ignored ones such as build trees).
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.h' '*.hpp' | sort -u)
else
  mapfile -t files < <(find modules servo tutorial test benchmark example fuzz -name '*.cpp' -o -name '*.h' -o -name '*.hpp' 2>/dev/null | sort)
fi
# A file listed by git but deleted from the work tree is not ours to format.
existing=()
for f in "${files[@]}"; do
  [ -f "$f" ] && existing+=("$f")
done
if [ ${#existing[@]} -eq 0 ]; then
  echo "format: no C++ files"
  exit 0
fi

if [ "$check" -eq 0 ]; then
  clang-format -i "${existing[@]}"
  echo "format: formatted ${#existing[@]} files"
  exit 0
fi

bad=()
for f in "${existing[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    bad+=("$f")
  fi
done
if [ ${#bad[@]} -ne 0 ]; then
  echo "format: ${#bad[@]} of ${#existing[@]} files need formatting; run scripts/format.sh (or clang-format -i FILE):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "format: all ${#existing[@]} files are formatted"
