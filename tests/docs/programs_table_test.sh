#!/usr/bin/env bash
# programs_table_test.sh LIST PAGE [--fedsim FEDSIM] [--without-row NAME] [--without-word NAME WORD]
#
# Checks that the tables of PAGE (a Markdown page) name every program of LIST, the build's own
# list of what it makes for users (build/fedsim_programs.txt, "name folder" a line: every
# executable target named fedsim or fedsim-*; cmake/FedsimModel.cmake), and with --fedsim every
# subcommand `fedsim --help` lists and each one's own subcommands. The rules
# (docs/programs.md says them too):
#   - a program is named by a table row whose first cell holds it in backticks: `fedsim-qtg`
#     (a first cell may hold several: `fedsim-bench-flight`, `fedsim-bench-navdb`);
#   - `fedsim X` by a row whose first cell holds `fedsim X`;
#   - `fedsim X Y` (X's own subcommand, `fedsim topic info`) by the row of `fedsim X` holding `Y`;
#   - and every `fedsim X` a first cell holds must be a subcommand fedsim has (no stale rows).
# Each one missing is printed by name; the exit status is 1 if any is.
# The negative controls check a copy of the page with one row taken out (--without-row NAME: the
# row whose first cell holds NAME) or one word taken out of a row (--without-word NAME WORD).
set -euo pipefail

list=$1 page=$2
shift 2
fedsim="" drop_row="" drop_word_row="" drop_word=""
while [ $# -gt 0 ]; do
  case $1 in
    --fedsim) fedsim=$2; shift 2 ;;
    --without-row) drop_row=$2; shift 2 ;;
    --without-word) drop_word_row=$2; drop_word=$3; shift 3 ;;
    *) echo "programs_table_test: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -s "$list" ] || { echo "programs_table_test: $list is missing or empty" >&2; exit 2; }
[ -f "$page" ] || { echo "programs_table_test: $page is missing" >&2; exit 2; }

# The table rows of the page: lines that start with '|', not the |---| separators.
mapfile -t rows < <(grep '^|' "$page" | grep -v '^| *-' || true)

# The backticked names in a row's first cell (no '|' inside them: a first cell is names only).
first_cell_names() {
  local cell=${1#|}
  cell=${cell%%|*}
  grep -o '`[^`]*`' <<<"$cell" | tr -d '`' || true
}

# The index of the row whose first cell holds NAME, or nothing.
row_of() {
  local i
  for i in "${!rows[@]}"; do
    if first_cell_names "${rows[$i]}" | grep -qxF -- "$1"; then
      echo "$i"
      return
    fi
  done
}

if [ -n "$drop_row" ]; then
  i=$(row_of "$drop_row")
  [ -n "$i" ] || { echo "programs_table_test: no row of '$drop_row' to take out" >&2; exit 2; }
  echo "negative control: the row of '$drop_row' taken out"
  unset "rows[$i]"
  rows=("${rows[@]}")
fi
if [ -n "$drop_word_row" ]; then
  i=$(row_of "$drop_word_row")
  [ -n "$i" ] || { echo "programs_table_test: no row of '$drop_word_row'" >&2; exit 2; }
  echo "negative control: \`$drop_word\` taken out of the row of '$drop_word_row'"
  rows[$i]=${rows[$i]//\`$drop_word\`/}
fi

missing=0
report_missing() {
  echo "$page: missing: $1"
  missing=$((missing + 1))
}

checked=0
while read -r name folder; do
  [ -n "$name" ] || continue
  checked=$((checked + 1))
  [ -n "$(row_of "$name")" ] || report_missing "program $name (built from $folder/)"
done <"$list"

# The subcommands a CLI11 --help lists: the lines under "Subcommands:", two spaces and a name.
subcommands_of() {
  "$@" --help | awk '/^Subcommands:/ {on = 1; next} on && /^  [a-z]/ {print $1}'
}

if [ -n "$fedsim" ]; then
  mapfile -t top < <(subcommands_of "$fedsim")
  [ ${#top[@]} -gt 0 ] || { echo "programs_table_test: '$fedsim --help' lists no subcommand" >&2; exit 2; }
  for sub in "${top[@]}"; do
    checked=$((checked + 1))
    i=$(row_of "fedsim $sub")
    if [ -z "$i" ]; then
      report_missing "subcommand \`fedsim $sub\`"
      continue
    fi
    for nested in $(subcommands_of "$fedsim" "$sub"); do
      checked=$((checked + 1))
      grep -qF -- "\`$nested\`" <<<"${rows[$i]}" || report_missing "subcommand \`fedsim $sub $nested\` (the row of \`fedsim $sub\` does not name \`$nested\`)"
    done
  done
  # No row for a subcommand fedsim does not have (a renamed or removed one).
  for row in "${rows[@]}"; do
    while read -r name; do
      [[ $name == "fedsim "* ]] || continue
      sub=${name#fedsim }
      printf '%s\n' "${top[@]}" | grep -qxF -- "$sub" ||
        { echo "$page: stale: a row for \`$name\`, which fedsim --help does not list"; missing=$((missing + 1)); }
    done < <(first_cell_names "$row")
  done
fi

if [ $missing -gt 0 ]; then
  echo "programs table check: FAILED, $missing of $checked missing or stale in $page"
  exit 1
fi
echo "programs table check: all $checked programs and subcommands named in $page"
