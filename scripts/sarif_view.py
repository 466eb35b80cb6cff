#!/usr/bin/python3
"""Render a SARIF 2.1.0 log as one static HTML page laid out like a code-scanning alert view
(GitHub's "Code scanning" alert page): per result the rule, its severity and description, the
file:line:col with the source lines around it and the message under the flagged line, the
related locations, and the code flow as numbered steps, each with its source line.

Only what the log says is shown; source lines are read from the files the log names, resolved
against --root. Used for docs/sarif.png (docs/reports.md); no network, standard library only.

Usage: sarif_view.py LOG.sarif --root DIR [--result N ...] > page.html
"""
import argparse
import html
import json
import os
import sys
from urllib.parse import unquote, urlparse

CSS = """
body { font: 14px/1.5 -apple-system, "Segoe UI", "DejaVu Sans", sans-serif; color: #1f2328;
       margin: 0; padding: 20px 28px; background: #fff; max-width: 1040px; }
.alert { border: 1px solid #d0d7de; border-radius: 6px; margin-bottom: 24px; }
.head { padding: 12px 16px; border-bottom: 1px solid #d0d7de; background: #f6f8fa; }
.head h2 { margin: 0 0 4px; font-size: 18px; font-weight: 600; }
.badge { display: inline-block; font-size: 12px; font-weight: 600; border-radius: 2em;
         padding: 0 8px; margin-right: 6px; border: 1px solid; }
.badge.error { color: #d1242f; border-color: #d1242f; }
.badge.warning { color: #9a6700; border-color: #9a6700; }
.badge.note { color: #0969da; border-color: #0969da; }
.meta { color: #59636e; font-size: 13px; }
.body { padding: 12px 16px; }
.file { font-family: "DejaVu Sans Mono", monospace; font-size: 12px; border: 1px solid #d0d7de;
        border-bottom: 0; border-radius: 6px 6px 0 0; background: #f6f8fa; padding: 6px 10px; }
table.code { border: 1px solid #d0d7de; border-radius: 0 0 6px 6px; border-collapse: separate;
             border-spacing: 0; width: 100%; font: 12px/1.6 "DejaVu Sans Mono", monospace; }
table.code td.n { color: #59636e; text-align: right; padding: 0 10px; width: 1%; user-select: none; }
table.code td.l { white-space: pre; padding-right: 10px; }
table.code tr.hit td { background: #fff8c5; }
table.code tr.msg td { padding: 0; }
.annot { margin: 4px 10px 6px 10px; border: 1px solid #d1242f; border-left-width: 4px;
         border-radius: 4px; padding: 6px 10px; font: 13px/1.4 -apple-system, "Segoe UI", "DejaVu Sans", sans-serif;
         white-space: normal; background: #fff; }
.annot.warning { border-color: #9a6700; }
h3 { font-size: 14px; margin: 16px 0 6px; }
ol.flow { padding-left: 0; list-style: none; margin: 0; }
ol.flow li { border: 1px solid #d0d7de; border-radius: 6px; margin-bottom: 6px; padding: 4px 10px; }
ol.flow .step { display: inline-block; min-width: 22px; height: 22px; line-height: 22px; text-align: center;
                border-radius: 50%; background: #0969da; color: #fff; font-size: 12px; font-weight: 600; margin-right: 8px; }
ol.flow .where { font: 12px "DejaVu Sans Mono", monospace; color: #0969da; }
ol.flow code { display: block; white-space: pre; font: 12px "DejaVu Sans Mono", monospace; background: #f6f8fa;
               padding: 1px 6px; margin: 3px 0; border-radius: 3px; }
ol.flow .msg { font-size: 12px; color: #59636e; }
ul.related { margin: 0; padding-left: 18px; font-size: 13px; }
ul.related .where { font: 12px "DejaVu Sans Mono", monospace; color: #0969da; }
"""


def source_lines(root, uri, cache={}):
    path = unquote(urlparse(uri).path) if uri.startswith("file://") else unquote(uri)
    if not os.path.isabs(path):
        path = os.path.join(root, path)
    if path not in cache:
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                cache[path] = f.read().split("\n")
        except OSError:
            cache[path] = []
    return cache[path]


def where(phys):
    uri = phys["artifactLocation"]["uri"]
    region = phys.get("region", {})
    text = uri
    if "startLine" in region:
        text += ":" + str(region["startLine"])
        if "startColumn" in region:
            text += ":" + str(region["startColumn"])
    return uri, region.get("startLine"), text


def snippet(root, phys, message, level, context=3):
    uri, line, text = where(phys)
    lines = source_lines(root, uri)
    out = ['<div class="file">%s</div><table class="code">' % html.escape(text)]
    if line and lines:
        for n in range(max(1, line - context), min(len(lines), line + context) + 1):
            out.append('<tr class="%s"><td class="n">%d</td><td class="l">%s</td></tr>'
                       % ("hit" if n == line else "", n, html.escape(lines[n - 1])))
            if n == line:
                out.append('<tr class="msg"><td></td><td><div class="annot %s">%s</div></td></tr>'
                           % (level, html.escape(message)))
    else:
        out.append('<tr class="msg"><td></td><td><div class="annot %s">%s</div></td></tr>'
                   % (level, html.escape(message)))
    out.append("</table>")
    return "".join(out)


def render(log, root, picked):
    run = log["runs"][0]
    driver = run["tool"]["driver"]
    rules = {r["id"]: r for r in driver.get("rules", [])}
    parts = []
    for i, res in enumerate(run.get("results", [])):
        if picked and i not in picked:
            continue
        rule = rules.get(res.get("ruleId"), {})
        level = res.get("level", "warning")
        desc = rule.get("shortDescription", {}).get("text", "")
        loc = res["locations"][0]["physicalLocation"]
        parts.append('<div class="alert"><div class="head"><h2>%s</h2>'
                     '<span class="badge %s">%s</span><span class="meta">%s &middot; tool %s %s</span></div>'
                     % (html.escape(res.get("ruleId", "")), level, level.capitalize(), html.escape(desc),
                        html.escape(driver.get("name", "")), html.escape(driver.get("version", ""))))
        parts.append('<div class="body">' + snippet(root, loc, res["message"]["text"], level))
        related = res.get("relatedLocations", [])
        if related:
            parts.append("<h3>Related locations</h3><ul class=\"related\">")
            for r in related:
                _, _, text = where(r["physicalLocation"])
                parts.append('<li><span class="where">%s</span> %s</li>'
                             % (html.escape(text), html.escape(r.get("message", {}).get("text", ""))))
            parts.append("</ul>")
        for flow in res.get("codeFlows", []):
            for thread in flow.get("threadFlows", []):
                steps = thread.get("locations", [])
                parts.append("<h3>Code flow: %d steps</h3><ol class=\"flow\">" % len(steps))
                for k, step in enumerate(steps, 1):
                    phys = step["location"]["physicalLocation"]
                    uri, line, text = where(phys)
                    lines = source_lines(root, uri)
                    src = lines[line - 1].strip() if line and line <= len(lines) else ""
                    parts.append('<li><span class="step">%d</span><span class="where">%s</span><code>%s</code>'
                                 '<span class="msg">%s</span></li>'
                                 % (k, html.escape(text), html.escape(src),
                                    html.escape(step["location"].get("message", {}).get("text", ""))))
                parts.append("</ol>")
        parts.append("</div></div>")
    return ('<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>SARIF alerts</title>'
            "<style>%s</style></head><body>%s</body></html>\n" % (CSS, "".join(parts)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("log")
    ap.add_argument("--root", default=".", help="directory that relative artifact URIs resolve against")
    ap.add_argument("--result", type=int, action="append", default=[], help="only result N (0-based)")
    a = ap.parse_args()
    with open(a.log) as f:
        log = json.load(f)
    sys.stdout.write(render(log, a.root, set(a.result)))


if __name__ == "__main__":
    main()
