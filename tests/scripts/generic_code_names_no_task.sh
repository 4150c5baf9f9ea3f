#!/usr/bin/env bash
# Generic code names no task: in framework/ outside the tasks' own folders (framework/envs/<task>/),
# no C++ string literal holds
#  - a task's name: a task folder's name, or one of TASK_WORDS as a word (the simulator may call
#    its soft body a rope: "rope" is allowed in framework/sim/);
#  - a task's label: one of LABELS as the whole literal or joined by '_' to a name
#    (task_success_rate_push); the labels that are also plain words (WORD_LABELS) only as a
#    metric name's suffix after 'expected' or 'rate' (expected_none, task_success_rate_none);
#  - a task's unit: one of UNITS as a word;
#  - a figure file: a *.png name a task's folder writes, or any *.png name in framework/report/
#    (the reports read which figures to show from data).
# Comments and #include lines are not read. Each finding is printed as FILE:LINE: "TEXT" names
# ..., and the exit code is 1; 0 when there is none.
# Usage: generic_code_names_no_task.sh [SOURCE_ROOT] (default: this checkout)
set -euo pipefail
cd "${1:-$(dirname "${BASH_SOURCE[0]}")/../..}"

TASK_WORDS="corridor rope knot knotting"
LABELS="push pull posterior-to-anterior anterior-to-posterior knot enclosed"
WORD_LABELS="none lateral vertical combined"
UNITS="cm"

tasks=$(find framework/envs -mindepth 1 -maxdepth 1 -type d -printf '%f ')
task_figures=$(find framework/envs -mindepth 2 \( -name '*.cpp' -o -name '*.hpp' \) -print0 |
  xargs -0 grep -ohE '[A-Za-z0-9_]+\.png' | sort -u | tr '\n' ' ' || true)

# Every string literal of the sources as FILE:LINE:TEXT (a raw string's lines joined by spaces).
literals() {
  awk '
    FNR == 1 { block = 0; raw = "" }
    {
      line = $0
      if (!block && raw == "" && line ~ /^[ \t]*#[ \t]*include/) next
      n = length(line); i = 1
      while (i <= n) {
        c = substr(line, i, 1)
        if (block) {
          if (substr(line, i, 2) == "*/") { block = 0; i += 2 } else i++
          continue
        }
        if (raw != "") {
          end = index(substr(line, i), raw)
          if (end == 0) { text = text substr(line, i) " "; break }
          print FILENAME ":" start ":" text substr(line, i, end - 1)
          i += end - 1 + length(raw); raw = ""
          continue
        }
        two = substr(line, i, 2)
        if (two == "//") break
        if (two == "/*") { block = 1; i += 2; continue }
        if (c == "\047") {  # a character literal
          j = i + 1
          while (j <= n && substr(line, j, 1) != "\047") j += (substr(line, j, 1) == "\\") ? 2 : 1
          i = j + 1
          continue
        }
        if (c == "R" && substr(line, i + 1, 1) == "\"" &&
            (i == 1 || substr(line, i - 1, 1) !~ /[A-Za-z0-9_]/)) {
          open = index(substr(line, i + 2), "(")
          raw = ")" substr(line, i + 2, open - 1) "\""
          start = FNR; text = ""
          i += 2 + open
          continue
        }
        if (c == "\"") {
          j = i + 1; text = ""
          while (j <= n && substr(line, j, 1) != "\"") {
            step = (substr(line, j, 1) == "\\") ? 2 : 1
            text = text substr(line, j, step); j += step
          }
          print FILENAME ":" FNR ":" text
          i = j + 1
          continue
        }
        i++
      }
    }' "$@"
}

find framework \( -name '*.cpp' -o -name '*.hpp' \) -not -path 'framework/envs/*/*' | sort |
  { mapfile -t files; literals "${files[@]}"; } |
  awk -v words="$TASK_WORDS" -v labels="$LABELS" -v word_labels="$WORD_LABELS" \
      -v units="$UNITS" -v tasks="$tasks" -v figures="$task_figures" '
    BEGIN {
      nw = split(words, word, " "); nl = split(labels, label, " ")
      nx = split(word_labels, word_label, " "); nu = split(units, unit, " ")
      nt = split(tasks, task, " "); nf = split(figures, figure, " ")
    }
    {
      first = index($0, ":"); rest = substr($0, first + 1); second = index(rest, ":")
      file = substr($0, 1, first - 1); text = substr(rest, second + 1)
      lower = tolower(text); why = ""
      nk = split(lower, token, /[^a-z0-9]+/)
      for (k = 1; k <= nk; k++) {
        for (w = 1; w <= nw; w++)
          if (token[k] == word[w] && !(word[w] == "rope" && file ~ /^framework\/sim\//))
            why = why " the task word \047" word[w] "\047"
        for (u = 1; u <= nu; u++) if (token[k] == unit[u]) why = why " the unit \047" unit[u] "\047"
      }
      for (t = 1; t <= nt; t++) if (index(lower, task[t])) why = why " the task \047" task[t] "\047"
      for (l = 1; l <= nl; l++)
        if (lower ~ ("(^|_)" label[l] "(_|$)")) why = why " the label \047" label[l] "\047"
      for (x = 1; x <= nx; x++)
        if (lower ~ ("(expected|rate)_" word_label[x] "$")) why = why " the label \047" word_label[x] "\047"
      for (f = 1; f <= nf; f++)
        if (index(text, figure[f])) why = why " the task figure \047" figure[f] "\047"
      if (file ~ /^framework\/report\// && text ~ /[A-Za-z0-9_]\.png/) why = why " a figure file"
      if (why != "") { print substr($0, 1, first + second - 1) ": \"" text "\" names" why; found = 1 }
    }
    END { exit found ? 1 : 0 }'
