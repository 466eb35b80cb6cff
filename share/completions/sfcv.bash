# bash completion for sfcv (installed in share/bash-completion/completions/sfcv).
_sfcv() {
  local cur prev words cword
  _init_completion 2>/dev/null || {
    cur="${COMP_WORDS[COMP_CWORD]}"
    prev="${COMP_WORDS[COMP_CWORD-1]}"
    words=("${COMP_WORDS[@]}")
    cword=$COMP_CWORD
  }
  local commands="check info lint simulate rsg query export report patterns plan merge"
  local sub="" i
  for ((i = 1; i < cword; i++)); do
    case "${words[i]}" in
      -*) ;;
      *) sub="${words[i]}"; break ;;
    esac
  done
  if [[ -z "$sub" ]]; then
    COMPREPLY=($(compgen -W "$commands --quiet --help --version" -- "$cur"))
    return
  fi
  case "$prev" in
    --engine) COMPREPLY=($(compgen -W "auto explicit bdd bmc kind ic3 nusmv" -- "$cur")); return ;;
    --trace) COMPREPLY=($(compgen -W "table json vcd csv none" -- "$cur")); return ;;
    --to) COMPREPLY=($(compgen -W "nusmv casmv promela aiger aag dot iec g7 plcopen" -- "$cur")); return ;;
    --format) COMPREPLY=($(compgen -W "auto xml iec g7 agrafe twincat l5x codesys simatic" -- "$cur")); return ;;
    --semantics) COMPREPLY=($(compgen -W "grafcet iec61131" -- "$cur")); return ;;
    --priority) COMPREPLY=($(compgen -W "standard none" -- "$cur")); return ;;
    --time) COMPREPLY=($(compgen -W "abstract discrete" -- "$cur")); return ;;
    --unwritten) COMPREPLY=($(compgen -W "free keep" -- "$cur")); return ;;
    --reorder) COMPREPLY=($(compgen -W "none once dynamic" -- "$cur")); return ;;
    --deadlock-paths) COMPREPLY=($(compgen -W "stutter drop" -- "$cur")); return ;;
    --checks) COMPREPLY=($(compgen -W "all none reachable dead-transitions reentry deadlock local-deadlock return conflicts stored-actions output-conflicts order-dependence instability" -- "$cur")); return ;;
    --ctl|--ltl|--pattern|--fair|--assume|--pou|--timeout|--memory|--max-states|--cycle|--depth|--threads|--max-nodes|--max-cycles|--use|--shard) return ;;
  esac
  if [[ "$cur" == -* ]]; then
    # The options of the subcommand, read from its own --help.
    local opts
    opts=$(sfcv "$sub" --help 2>/dev/null | grep -oE -- '--[a-z][a-z0-9-]*' | sort -u)
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
    return
  fi
  COMPREPLY=($(compgen -f -- "$cur"))
}
complete -o filenames -F _sfcv sfcv
