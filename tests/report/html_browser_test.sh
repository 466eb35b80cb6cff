#!/bin/sh
# The HTML report in a real browser (Debian's chromium, headless): the chemical plant's
# counterexample to AG !(V2 & V4), stepped with the arrow key to the cycle where V2 and V4 open
# together; the highlighted steps and the shown outputs must be the trace's. Keeps a screenshot.
# Usage: html_browser_test.sh SFCV SOURCE_DIR OUT_DIR. Exit 77 (skipped) without chromium.
set -eu
. "$(dirname "$0")/browser_common.sh"
plant="$src/examples/chemical_plant/chemical_plant.st"
"$sfcv" check "$plant" --quiet --ctl 'AG !(V2 & V4)' --json --html "$dir/check.html" >"$dir/result.json" || [ $? -eq 1 ]
# The saved result renders to the same page.
"$sfcv" report "$dir/result.json" --html "$out/report.html"
cmp "$dir/check.html" "$out/report.html"
# The cycle where V2 and V4 are both open, from the result itself.
cycle=$(/usr/bin/python3 -c '
import json, sys
t = json.load(open(sys.argv[1]))["properties"][0]["trace"]
print(next(i for i, s in enumerate(t["steps"]) if s["values"].get("V2") is True and s["values"].get("V4") is True))
' "$dir/result.json")
presses=$(printf "%${cycle}s" "" | tr " " R)
url="file://$out/report.html#trace=0&press=$presses"
flags="--headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=3000"
# shellcheck disable=SC2086
timeout 120 "$browser" $flags --dump-dom "$url" >"$dir/dom.html" 2>"$dir/chromium.log" || { cat "$dir/chromium.log"; exit 1; }
# shellcheck disable=SC2086
timeout 120 "$browser" $flags --window-size=1400,1500 --screenshot="$out/report.png" "$url" >/dev/null 2>&1 || true
/usr/bin/python3 - "$dir/result.json" "$dir/dom.html" "$cycle" <<'PY'
import json, re, sys
from html.parser import HTMLParser

trace = json.load(open(sys.argv[1]))["properties"][0]["trace"]
cycle = int(sys.argv[3])
step = trace["steps"][cycle]

class Dom(HTMLParser):
    """Texts of the highlighted SVG nodes, and the panel's fields."""
    def __init__(self):
        super().__init__()
        self.stack, self.active, self.fired, self.fields = [], [], 0, {}
        self.on = None
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        classes = (a.get("class") or "").split()
        mark = None
        if tag == "g" and "active" in classes:
            mark = "active"
        if tag == "g" and "fired" in classes:
            self.fired += 1
        if a.get("id") in ("cycle-label", "active-steps"):
            mark = a["id"]
        if a.get("id") == "values":
            self.on = a.get("data-on", "")
        self.stack.append((tag, mark))
        if mark == "active":
            self.active.append("")
    def handle_endtag(self, tag):
        while self.stack:
            if self.stack.pop()[0] == tag:
                break
    def handle_data(self, data):
        marks = [m for _, m in self.stack if m]
        if not marks:
            return
        if marks[-1] == "active" and self.stack[-1][0] == "text":
            self.active[-1] += data.strip()
        elif marks[-1] != "active":
            self.fields[marks[-1]] = self.fields.get(marks[-1], "") + data

dom = Dom()
dom.feed(open(sys.argv[2]).read())
expected = sorted(name.split(".")[-1] for name in step["active_steps"])
problems = []
if sorted(dom.active) != expected:
    problems.append(f"highlighted steps {sorted(dom.active)} != the trace's {expected}")
if dom.fired != len(step["fired"]):
    problems.append(f"{dom.fired} highlighted transitions != {len(step['fired'])} fired")
if not dom.fields.get("cycle-label", "").startswith(f"cycle {cycle} of "):
    problems.append(f"cycle label {dom.fields.get('cycle-label')!r}")
if dom.fields.get("active-steps", "").split() != step["active_steps"]:
    problems.append(f"active steps shown {dom.fields.get('active-steps')!r}")
shown_on = set((dom.on or "").split())
trace_on = {n for n, v in step["values"].items() if v is True}
# The page shows "Plant.V2" once, as the property's atom "V2".
trace_on = {n for n in trace_on if n.split(".")[-1] == n or n.split(".")[-1] not in step["values"]}
if shown_on != trace_on or not {"V2", "V4"} <= shown_on:
    problems.append(f"outputs shown on {sorted(shown_on)} != the trace's {sorted(trace_on)}")
for p in problems:
    print("FAIL:", p)
print(f"cycle {cycle}: highlighted {sorted(dom.active)}, outputs on {sorted(shown_on)}")
sys.exit(1 if problems else 0)
PY
