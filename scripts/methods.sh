# methods.sh - scripts/methods.tsv (the one list of methods) for bash
# scripts: source it, then ask. Sets METHODS_TSV (unless the caller did).
#   methods_keys [KIND...]   the keys of those kinds (all when none), in the
#                            file's order, on one line
#   method_get KEY FIELD     one field of a key's row by its column name
#                            (label, colour, pt, kind, method, variant,
#                            command); empty for an unknown key
#   methods_binaries [KIND...]  the commands' programs, each once
METHODS_TSV=${METHODS_TSV:-$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/methods.tsv}
[ -r "$METHODS_TSV" ] || { echo "methods.sh: $METHODS_TSV not readable" >&2; return 1 2>/dev/null || exit 1; }

methods_keys() {
  awk -F'\t' -v kinds=" $* " '/^#/ || $1 == "key" { next }
    kinds == "  " || index(kinds, " " $5 " ") { printf "%s%s", (k++ ? " " : ""), $1 } END { printf "\n" }' "$METHODS_TSV"
}

method_get() {
  awk -F'\t' -v k="$1" -v f="$2" '/^#/ { next }
    $1 == "key" { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $1 == k && (f in c) { print $c[f]; exit }' "$METHODS_TSV"
}

methods_binaries() {
  local k
  for k in $(methods_keys "$@"); do method_get "$k" command | cut -d' ' -f1; done | awk '!s[$0]++' | tr '\n' ' ' | sed 's/ $//'
}
