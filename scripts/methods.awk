# methods.awk - scripts/methods.tsv (the one list of methods) for awk
# programs: awk -v methods=scripts/methods.tsv -f scripts/methods.awk -f PROG.awk
#   mlabel(k), mcolour(k), mpt(k), mkind(k), mfield(k, name)  a key's fields
#       (an unknown key: its own name, #000000, 8, "")
#   mkeys(kinds)  the keys of those kinds ("pd iter", ...; "" for all), in
#       the file's order, separated by spaces
function methods_load(   line, a, nf, i, col, nk) {
  if (methods == "") { print "methods.awk: -v methods=FILE not given" > "/dev/stderr"; exit 1 }
  while ((getline line < methods) > 0) {
    if (line ~ /^#/ || line == "") continue
    nf = split(line, a, "\t")
    if (a[1] == "key") { for (i = 1; i <= nf; i++) col[i] = a[i]; continue }
    M_order[++nk] = a[1]
    for (i = 1; i <= nf; i++) M_[a[1], col[i]] = a[i]
  }
  close(methods)
  M_n = nk
  if (!M_n) { print "methods.awk: no methods in " methods > "/dev/stderr"; exit 1 }
}
BEGIN { methods_load() }
function mfield(k, name) { return ((k, name) in M_) ? M_[k, name] : "" }
function mlabel(k) { return ((k, "label") in M_) ? M_[k, "label"] : k }
function mcolour(k) { return ((k, "colour") in M_) ? M_[k, "colour"] : "#000000" }
function mpt(k) { return ((k, "pt") in M_) ? M_[k, "pt"] : 8 }
function mkind(k) { return mfield(k, "kind") }
function mkeys(kinds,   i, s, k) {
  s = ""
  for (i = 1; i <= M_n; i++) { k = M_order[i]
    if (kinds == "" || index(" " kinds " ", " " M_[k, "kind"] " ")) s = s (s == "" ? "" : " ") k }
  return s
}
