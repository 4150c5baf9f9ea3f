#!/usr/bin/env bash
# Tests of generic_code_names_no_task.sh on a made-up tree: a task's name, label, unit and
# figure file in generic code are found (in strings, not in comments or #include lines, and
# not in the task's own folder); a clean tree passes.
set -euo pipefail
check="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/generic_code_names_no_task.sh"
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
mkdir -p "$tree/framework/envs/lift_box" "$tree/framework/report" "$tree/framework/core"
cat >"$tree/framework/envs/lift_box/lift_box.cpp" <<'CPP'
#include "envs/lift_box/lift_box.hpp"
const char* kLabels[] = {"push", "lift_box"};  // the task's own folder may name it
void figure(const std::string& d) { write(d + "/lifted.png"); }
CPP
cat >"$tree/framework/core/clean.cpp" <<'CPP'
#include "envs/lift_box/lift_box.hpp"  // an include names a file, not a task
// A comment may say corridor, push, cm or lifted.png.
const char* kText = "push back along the ray; none of them";  /* "rope" */
const char kQuote = '"';
const char* kSql = R"sql(SELECT "name" FROM runs)sql";
CPP
bash "$check" "$tree"  # clean: exit 0

cat >"$tree/framework/report/named.cpp" <<'CPP'
const char* a = "lift_box runs";
const char* b = "task_success_rate_push";
const char* c = "expected_none";
const char* d = "error (cm)";
const char* e = "lifted.png";
const char* f = R"x(a corridor
x)x";
CPP
if output=$(bash "$check" "$tree"); then
  echo "FAIL: names in generic code not found"; exit 1
fi
for expected in "named.cpp:1: \"lift_box runs\" names the task 'lift_box'" \
                "named.cpp:2: \"task_success_rate_push\" names the label 'push'" \
                "named.cpp:3: \"expected_none\" names the label 'none'" \
                "named.cpp:4: \"error (cm)\" names the unit 'cm'" \
                "named.cpp:5: \"lifted.png\" names the task figure 'lifted.png' a figure file" \
                "named.cpp:6: \"a corridor x\" names the task word 'corridor'"; do
  if ! grep -qF "$expected" <<<"$output"; then
    echo "FAIL: expected '$expected' in:"; echo "$output"; exit 1
  fi
done
if [ "$(wc -l <<<"$output")" -ne 6 ]; then echo "FAIL: findings beyond named.cpp:"; echo "$output"; exit 1; fi
echo "ok"
