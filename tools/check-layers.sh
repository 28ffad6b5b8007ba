#!/usr/bin/env bash
# The layering check (CTest `layers`): who may include and link whom.
#   tools/check-layers.sh [SOURCE_DIR]
# Dependencies point down, never back up:
#   units -> core -> protocol (the codec) / hal -> app -> host -> boards, tools, host_sim
# Rules, by the folder of the including file:
#   firmware/units     only units
#   firmware/core      only units, core
#   hal                only units, hal
#   firmware/protocol  only units, protocol, core (the codec reads the core's option bits)
#   firmware/app       only units, core, hal, protocol, app
#   host               only the firmware libraries and host (host-only helpers
#                      that boards, tools and host_sim share)
#   boards, tools      anything but host_sim
# Checked: every #include (quoted or angled) that names a file of the tree,
# resolved like the compiler does (the includer's folder first, then every
# include/ folder), and the targets and source paths that CMake files name.
# Exit 0 when all hold; else 1, each violation as file:line: what, and the rule.
set -euo pipefail -f  # -f: no globbing of the words read from CMake files
root=$(cd "${1:-$(dirname "$0")/..}" && pwd)
cd "$root"

# The area of a path, in $area (no subshell: called for every include).
area_of() {
  case $1 in
    firmware/units/*) area=units ;;
    firmware/core/*) area=core ;;
    firmware/protocol/*) area=protocol ;;
    firmware/app/*) area=app ;;
    hal/*) area=hal ;;
    host/*) area=host ;;
    boards/*) area=boards ;;
    tools/*) area=tools ;;
    host_sim/*) area=host_sim ;;
    *) area=other ;;
  esac
}

# "only A B" or "not A B"; none when the area has no rule.
declare -A rule=(
  [units]="only units"
  [core]="only units core"
  [hal]="only units hal"
  [protocol]="only units protocol core"
  [app]="only units core hal protocol app"
  [host]="only units core hal protocol app host"
  [boards]="not host_sim"
  [tools]="not host_sim"
)

allowed() {  # from-area to-area
  local r=${rule[$1]:-}
  [[ -z $r ]] && return 0
  local list=" ${r#* } "
  if [[ ${r%% *} == only ]]; then [[ $list == *" $2 "* ]]; else [[ $list != *" $2 "* ]]; fi
}

rule_text() {
  local r=${rule[$1]}
  local list=${r#* }
  if [[ ${r%% *} == only ]]; then echo "$1 may use only ${list// /, }"; else echo "$1 may not use ${list// /, }"; fi
}

areas=(firmware hal host boards tools host_sim)
failures=0
fail() {  # where what from-area
  echo "$1: $2 ($(rule_text "$3"))"
  failures=$((failures + 1))
}

# Every header under an include/ folder, by the name it is included as.
declare -A header
while IFS= read -r f; do
  name=${f##*/include/}
  header[$name]="${header[$name]:-} $f"
done < <(find "${areas[@]}" -path '*/include/*' -type f \( -name '*.hpp' -o -name '*.h' \) | sort)

# Includes.
inc_re='^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]([^">]+)[">]'
while IFS= read -r f; do
  area_of "$f"
  from=$area
  [[ -z ${rule[$from]:-} ]] && continue
  dir=${f%/*}
  while IFS=: read -r line text; do
    [[ $text =~ $inc_re ]] || continue
    name=${BASH_REMATCH[1]}
    if [[ -f $dir/$name ]]; then
      cands=$(realpath -m --relative-to="$root" "$dir/$name")
    else
      cands=${header[$name]:-}
    fi
    [[ -z $cands ]] && continue  # not a file of the tree (standard or third-party header)
    ok=0 first="" first_area=""
    for c in $cands; do
      area_of "$c"
      [[ -z $first ]] && first=$c first_area=$area
      if allowed "$from" "$area"; then ok=1; break; fi
    done
    ((ok)) || fail "$f:$line" "includes $name ($first, $first_area)" "$from"
  done < <(grep -nE "$inc_re" "$f")
done < <(find "${areas[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.c' \) | sort)

# CMake: the targets each folder defines, then what each ruled CMake file names.
declare -A target
while IFS= read -r f; do
  area_of "$f"
  while IFS= read -r t; do target[$t]=$area; done < <(
    sed 's/#.*//' "$f" | grep -oE 'add_(library|executable)\([[:space:]]*[A-Za-z0-9_.+-]+' | sed -E 's/.*\([[:space:]]*//')
done < <(find "${areas[@]}" -type f \( -name CMakeLists.txt -o -name '*.cmake' \) | sort)

while IFS= read -r f; do
  area_of "$f"
  from=$area
  [[ -z ${rule[$from]:-} ]] && continue
  dir=${f%/*}
  n=0
  while IFS= read -r text; do
    n=$((n + 1))
    code=${text%%#*}  # comments may name anything
    for tok in $(grep -oE '[A-Za-z0-9_.+-]+' <<<"$code" || true); do
      to=${target[$tok]:-}
      if [[ -n $to ]] && ! allowed "$from" "$to"; then fail "$f:$n" "names target $tok ($to)" "$from"; fi
    done
    for p in $(grep -oE '\$\{(PROJECT_SOURCE_DIR|CMAKE_SOURCE_DIR|CMAKE_CURRENT_SOURCE_DIR|CMAKE_CURRENT_LIST_DIR)\}[^[:space:])"]*' <<<"$code" || true); do
      # shellcheck disable=SC2016  # the CMake variable's name, literally
      case $p in
        '${CMAKE_CURRENT_SOURCE_DIR}'* | '${CMAKE_CURRENT_LIST_DIR}'*) rel=$dir/${p#*\}} ;;
        *) rel=.${p#*\}} ;;
      esac
      rel=$(realpath -m --relative-to="$root" "$rel")
      area_of "$rel/"
      to=$area
      if [[ $to != other ]] && ! allowed "$from" "$to"; then fail "$f:$n" "names path $rel ($to)" "$from"; fi
    done
  done <"$f"
done < <(find "${areas[@]}" -type f \( -name CMakeLists.txt -o -name '*.cmake' \) | sort)

if ((failures)); then
  echo "check-layers: $failures violation(s)"
  exit 1
fi
echo "check-layers: every include and CMake reference points down"
