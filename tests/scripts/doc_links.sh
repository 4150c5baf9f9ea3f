#!/usr/bin/env bash
# doc_links.sh PROJECT_DIR: every relative link [text](target) in README.md and docs/*.md, outside
# code blocks, names a file that exists and, with #fragment, a heading of that file (GitHub's
# anchor: lower case, punctuation dropped, spaces as hyphens). Prints each broken link; exit 1
# if there is one.
set -euo pipefail
cd "$1"

outside_code() { awk '/^```/ { code = !code; next } !code' "$1"; }
anchors() {
  outside_code "$1" | grep -E '^#{1,6} ' | sed -E 's/^#+ +//' | tr 'A-Z' 'a-z' |
    sed -E 's/[^a-z0-9 _-]//g; s/ /-/g'
}

broken=0
for page in README.md docs/*.md; do
  dir=$(dirname "$page")
  while IFS= read -r target; do
    case "$target" in http://* | https://* | mailto:*) continue ;; esac
    path=${target%%#*}
    fragment=""
    [[ $target == *"#"* ]] && fragment=${target#*#}
    file=$page
    [ -n "$path" ] && file=$dir/$path
    if [ ! -e "$file" ]; then
      echo "$page: ($target): no file $file"
      broken=1
    elif [ -n "$fragment" ] && ! anchors "$file" | grep -qxF -- "$fragment"; then
      echo "$page: ($target): no heading '$fragment' in $file"
      broken=1
    fi
  done < <(outside_code "$page" | grep -oE '\]\([^)[:space:]]+\)' | sed -E 's/^\]\(//; s/\)$//' || true)
done
exit $broken
