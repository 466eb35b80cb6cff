#!/usr/bin/env bash
# bench/corpus_verdicts.sh: the verdicts of two sfcv binaries on every file of the shared corpus,
# side by side, as TSV (docs/examples.md, "Verdicts on the shared corpus that changed in round 3").
# Each file is checked with the defaults (all standard checks, --engine auto) and the options that
# docs/examples.md gives it; the two runs of a file are sequential, one at a time. Downloads nothing.
#
#   SFCV_CORPUS=/work/shared/corpus bench/corpus_verdicts.sh BEFORE_SFCV AFTER_SFCV [--timeout S] [FILE...]
#
# Columns: file, options, check, before, after, changed (yes, no, or "new check": one the first
# binary does not have), decided_by before/after, findings before/after. A file both refuse gives
# one row with check "(load)"; a run that ends without a report gives "no report (exit N)" for
# every check of the other. KEEP_JSON=DIR keeps both reports of each file. FILE... restricts the
# run to the corpus files whose names start so.
set -euo pipefail

[[ $# -ge 2 ]] || { sed -n '2,13p' "$0"; exit 2; }
before=$1
after=$2
shift 2
corpus=${SFCV_CORPUS:?set SFCV_CORPUS to the shared corpus folder}
limit=30
only=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --timeout) limit=$2; shift ;;
    *) only+=("$1") ;;
  esac
  shift
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# file <TAB> options: the runs of docs/examples.md's corpus table. 05 is a template whose XXXX is
# an identifier (the matiec test substitutes qualifier names); N is one of them.
runs() {
  local f
  for f in "$corpus"/*; do
    local name=${f##*/}
    case $name in
      MANIFEST*) ;;
      07_*) printf '%s\t\n%s\t--pou Stamp --pou Magazin --pou Crane\n' "$name" "$name" ;;
      *) printf '%s\t\n' "$name" ;;
    esac
  done
}

selected() {
  [[ ${#only[@]} -eq 0 ]] && return 0
  local o
  for o in "${only[@]}"; do [[ $1 == "$o"* ]] && return 0; done
  return 1
}

# run BINARY FILE OPTIONS OUT: one check run, its JSON (or nothing) in OUT, its exit code in OUT.rc
run() {
  local bin=$1 file=$2 opts=$3 out=$4
  # shellcheck disable=SC2086  # OPTIONS is a list of words
  set +e
  "$bin" check "$file" --json --timeout "$limit" $opts >"$out" 2>"$out.err"
  echo $? >"$out.rc"
  set -e
}

printf 'file\toptions\tcheck\tbefore\tafter\tchanged\tby_before\tby_after\tfindings_before\tfindings_after\n'
while IFS=$'\t' read -r name opts; do
  selected "$name" || continue
  file=$corpus/$name
  if [[ $name == *.tmpl ]]; then
    sed 's/XXXX/N/g' "$file" >"$tmp/${name%.tmpl}"
    file=$tmp/${name%.tmpl}
  fi
  run "$before" "$file" "$opts" "$tmp/before.json"
  run "$after" "$file" "$opts" "$tmp/after.json"
  if [[ -n ${KEEP_JSON:-} ]]; then  # keep both reports for reading the findings
    mkdir -p "$KEEP_JSON"
    tag=$name${opts:+_pou}
    cp "$tmp/before.json" "$KEEP_JSON/$tag.before.json"
    cp "$tmp/after.json" "$KEEP_JSON/$tag.after.json"
  fi
  python3 - "$name" "$opts" "$tmp/before.json" "$tmp/after.json" <<'EOF'
import json, sys

name, opts, paths = sys.argv[1], sys.argv[2], sys.argv[3:]

def read(path):
    """check -> (verdict, decided_by, findings_total), or the run's status when it gave none."""
    rc = int(open(path + ".rc").read())
    try:
        doc = json.load(open(path))
    except (OSError, ValueError):
        doc = {}
    if not doc.get("properties"):
        return "refused (exit 2)" if rc == 2 else f"no report (exit {rc})"
    return {p.get("check") or p.get("name"): (p.get("verdict"), p.get("decided_by") or "",
                                              str(p.get("findings_total", "")))
            for p in doc["properties"]}

b, a = read(paths[0]), read(paths[1])
if isinstance(b, str) and isinstance(a, str):  # refused (or lost) by both: one row
    b, a = {"(load)": (b, "", "")}, {"(load)": (a, "", "")}
elif isinstance(b, str):  # a run without a report loses every verdict of the other's
    b = {c: (b, "", "") for c in a}
elif isinstance(a, str):
    a = {c: (a, "", "") for c in b}
for check in list(b) + [c for c in a if c not in b]:
    vb, byb, fb = b.get(check, ("-", "", ""))
    va, bya, fa = a.get(check, ("-", "", ""))
    changed = "new check" if vb == "-" else "yes" if vb != va else "no"
    print("\t".join([name, opts, check, vb, va, changed, byb, bya, fb, fa]))
EOF
done < <(runs)
