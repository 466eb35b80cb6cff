#!/bin/sh
# The Grafcet parts of the HTML reports in a real browser (Debian's chromium, headless): the
# pallet transfer's counterexample to AG !(X10 & X25), played to its last situation, must
# highlight that step situation on the situation graph; `sfcv query --html` must show the
# answers `sfcv query --json` gives. Keeps screenshots.
# Usage: html_grafcet_browser_test.sh SFCV SOURCE_DIR OUT_DIR. Exit 77 (skipped) without chromium.
set -eu
. "$(dirname "$0")/browser_common.sh"
pallet="$src/examples/pallet_transfer/pallet_transfer.g7"
"$sfcv" check "$pallet" --quiet --ctl 'AG !(X10 & X25)' --json --html "$out/grafcet.html" >"$dir/result.json" || [ $? -eq 1 ]
q1='Act({10, 25})'
q2='Y - Pred(Y0, T)'
"$sfcv" query "$pallet" "$q1" "$q2" --json >"$dir/answers.json"
"$sfcv" query "$pallet" "$q1" "$q2" --html "$out/query.html" >/dev/null
flags="--headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=3000"
# shellcheck disable=SC2086
timeout 120 "$browser" $flags --dump-dom "file://$out/grafcet.html#trace=0&press=E" >"$dir/grafcet_dom.html" 2>"$dir/chromium.log" || { cat "$dir/chromium.log"; exit 1; }
# shellcheck disable=SC2086
timeout 120 "$browser" $flags --dump-dom "file://$out/query.html" >"$dir/query_dom.html" 2>>"$dir/chromium.log" || { cat "$dir/chromium.log"; exit 1; }
# shellcheck disable=SC2086
timeout 120 "$browser" $flags --window-size=1400,1800 --screenshot="$out/grafcet.png" "file://$out/grafcet.html#trace=0&press=E" >/dev/null 2>&1 || true
# shellcheck disable=SC2086
timeout 120 "$browser" $flags --window-size=1200,1400 --screenshot="$out/query.png" "file://$out/query.html" >/dev/null 2>&1 || true
/usr/bin/python3 - "$dir/result.json" "$dir/grafcet_dom.html" "$dir/answers.json" "$dir/query_dom.html" <<'PY'
import json, sys
from html.parser import HTMLParser

class Dom(HTMLParser):
    """The texts inside the elements whose id or class a test names."""
    def __init__(self):
        super().__init__()
        self.stack = []   # (tag, id, classes)
        self.texts = {}   # key -> list of texts
        self.groups = []  # [(id, classes, [texts])] of the situation graph's <g> nodes
        self.rows = []    # query table rows: [[cell texts]]
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        classes = (a.get("class") or "").split()
        self.stack.append((tag, a.get("id"), classes))
        if tag == "g" and "node" in classes and any(i == "situations-svg" for _, i, _ in self.stack):
            self.groups.append((a.get("id"), classes, []))
        if tag == "tr" and "query" in classes:
            self.rows.append([])
        if tag == "td" and self.rows and any("query" in c for t, _, c in self.stack if t == "tr"):
            self.rows[-1].append("")
    def handle_endtag(self, tag):
        while self.stack:
            if self.stack.pop()[0] == tag:
                break
    def handle_data(self, data):
        tags = [t for t, _, _ in self.stack]
        ids = [i for _, i, _ in self.stack]
        if "situations-svg" in ids and tags and tags[-1] == "text" and self.groups:
            self.groups[-1][2].append(data.strip())
        if "situations-note" in ids:
            self.texts["note"] = self.texts.get("note", "") + data
        if self.rows and "td" in tags and any("query" in c for t, _, c in self.stack if t == "tr"):
            self.rows[-1][-1] += data

problems = []
trace = json.load(open(sys.argv[1]))["properties"][0]["trace"]
last = trace["steps"][-1]
dom = Dom()
dom.feed(open(sys.argv[2]).read())
active = [g for g in dom.groups if "active" in g[1]]
if len(dom.groups) == 0:
    problems.append("no situation graph nodes in the page")
if len(active) != 1:
    problems.append(f"{len(active)} highlighted situations, expected 1")
else:
    label = active[0][2][0] if active[0][2] else ""
    shown = sorted(s.strip() for s in label.strip("{}").split(","))
    if shown != sorted(last["active_steps"]):
        problems.append(f"highlighted situation {label!r} != the trace's last {last['active_steps']}")
    print(f"last situation {sorted(last['active_steps'])}: highlighted {label!r} ({len(dom.groups)} nodes drawn)")

answers = json.load(open(sys.argv[3]))["queries"]
q = Dom()
q.feed(open(sys.argv[4]).read())
if len(q.rows) != len(answers):
    problems.append(f"{len(q.rows)} query rows != {len(answers)} answers")
for row, a in zip(q.rows, answers):
    if row[0].strip() != a["query"]:
        problems.append(f"query {row[0]!r} != {a['query']!r}")
    if not row[1].strip().startswith(f"{a['count']} "):
        problems.append(f"answer {row[1]!r} != count {a['count']}")
    listed = row[3]
    first = a["elements"][0]["text"] if a["elements"] else None
    if first and first not in listed:
        problems.append(f"first element {first!r} not listed")
    print(f"query {a['query']!r}: {row[1].strip()!r}")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
PY
