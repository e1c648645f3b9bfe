#!/usr/bin/env bash
# test_cycles.sh BUILD_DIR - no call cycles between source files.
#
# The file-level graph of every C/C++ (and CUDA) source of the project
# outside the tests (src/, analysis/, baselines/, python/src/): an edge
# A -> B when A's object file uses a symbol that B's object file defines
# (nm: undefined vs strong global definitions; weak ones, as C++ inline
# functions and templates, belong to every user and make no edge). The
# objects are BUILD_DIR's (each mapped back to its source through CMake's
# CMakeFiles/<target>.dir/<path>.o layout; objects older than their
# source, or in nested build trees such as the Python package's, are left
# out); a source without an object is compiled here (the Python binding,
# which scikit-build builds elsewhere, needs Python.h and NumPy's headers:
# without them that part is skipped with a message). Fails naming each
# cycle, file by file with one symbol per step, and fails too when a
# source could not be checked. Starts with a self-test: two generated
# files that call each other must be reported, a chain must not.
set -u
B=$(cd "${1:?usage: test_cycles.sh BUILD_DIR}" && pwd)
ROOT=$(cd "$(dirname "$0")/.." && pwd)
CC=${CC:-cc}
CXX=${CXX:-c++}
T=$(mktemp -d /tmp/cfpo-cycles-XXXXXX)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
ok() { pass=$((pass + 1)); }

# symbols OBJLIST: "SOURCE OBJECT" lines in, "D|U SOURCE SYMBOL" lines out.
symbols() {
  while read -r src obj; do
    nm -P -g "$obj" 2>/dev/null | awk -v s="$src" '
      $2 == "U" { print "U", s, $1; next }
      $2 ~ /^[WwVv]$/ { next }
      NF >= 2 { print "D", s, $1 }'
  done <"$1"
}

# cycles: "D|U SOURCE SYMBOL" lines in; prints one line per cycle between
# files ("cycle: a.c -> b.c (sym) -> a.c (sym)") and exits 1 if any.
cycles() {
  awk '
    $1 == "D" { if (!(($3, $2) in seen)) { seen[$3, $2] = 1; def[$3] = def[$3] " " $2 } next }
    $1 == "U" { use[++nu] = $2 SUBSEP $3; node[$2] = 1; next }
    END {
      for (k = 1; k <= nu; k++) {
        split(use[k], p, SUBSEP); a = p[1]; sym = p[2]
        if (!(sym in def)) continue
        m = split(def[sym], d, " ")
        for (j = 1; j <= m; j++) {
          b = d[j]
          if (b == a || ((a, b) in edge)) continue
          edge[a, b] = sym; node[b] = 1
          out[a] = out[a] " " b
        }
      }
      # Reachability from each file, breadth first.
      for (s in node) {
        delete q; h = 1; t = 0
        q[++t] = s; reach[s, s] = 1
        while (h <= t) {
          u = q[h++]; m = split(out[u], o, " ")
          for (j = 1; j <= m; j++) if (!((s, o[j]) in reach)) { reach[s, o[j]] = 1; q[++t] = o[j] }
        }
      }
      found = 0
      for (s in node) {
        if (s in done) continue
        # s with the files it reaches and that reach it: one component;
        # its first file by name stands for it.
        rep = s; cnt = 0
        for (v in node) if ((s, v) in reach && (v, s) in reach) { cnt++; if (v < rep) rep = v; comp[v] = s }
        for (v in node) if ((v in comp) && comp[v] == s) done[v] = 1
        if (cnt < 2) continue
        found++
        # The shortest way back from rep to rep inside the component.
        delete q; delete prev; h = 1; t = 0
        m = split(out[rep], o, " ")
        for (j = 1; j <= m; j++) if ((o[j] in comp) && comp[o[j]] == s && !(o[j] in prev)) { prev[o[j]] = rep; q[++t] = o[j] }
        while (h <= t && !(rep in prev)) {
          u = q[h++]; m = split(out[u], o, " ")
          for (j = 1; j <= m; j++)
            if ((o[j] in comp) && comp[o[j]] == s && !(o[j] in prev)) { prev[o[j]] = u; q[++t] = o[j] }
        }
        path = rep; v = rep
        do { u = prev[v]; path = u " -> " v " (" edge[u, v] ")" substr(path, length(v) + 1); v = u } while (v != rep)
        members = ""
        for (v in node) if ((v in comp) && comp[v] == s) members = members " " v
        print "cycle: " path
        print "  component of " cnt " files:" members
      }
      exit found ? 1 : 0
    }'
}

# ---- self-test: a cycle of two files is found, a chain is not.
mkdir -p "$T/self"
cat >"$T/self/a.c" <<'EOF'
int b_fn(int);
int a_fn(int x) { return x > 0 ? b_fn(x - 1) : 0; }
EOF
cat >"$T/self/b.c" <<'EOF'
int a_fn(int);
int b_fn(int x) { return x > 0 ? a_fn(x - 1) : 1; }
EOF
cat >"$T/self/c.c" <<'EOF'
int a_fn(int);
int c_fn(int x) { return a_fn(x); }
EOF
cat >"$T/self/d.c" <<'EOF'
int d_fn(int x) { return x; }
EOF
cat >"$T/self/e.c" <<'EOF'
int d_fn(int);
int e_fn(int x) { return d_fn(x); }
EOF
built=1
for f in a b c d e; do "$CC" -c -o "$T/self/$f.o" "$T/self/$f.c" || built=0; done
if [ $built -eq 1 ]; then
  printf 'a.c %s\nb.c %s\nc.c %s\n' "$T/self/a.o" "$T/self/b.o" "$T/self/c.o" >"$T/self/cyc.list"
  printf 'c.c %s\nd.c %s\ne.c %s\n' "$T/self/c.o" "$T/self/d.o" "$T/self/e.o" >"$T/self/chain.list"
  symbols "$T/self/cyc.list" | cycles >"$T/self/cyc.out"
  rc=$?
  if [ $rc -eq 1 ] && grep -q '^cycle: a.c -> b.c (b_fn) -> a.c (a_fn)$' "$T/self/cyc.out" \
     && grep -q 'component of 2 files' "$T/self/cyc.out"; then ok
  else bad "self-test: a.c <-> b.c not reported (rc $rc): $(cat "$T/self/cyc.out")"; fi
  symbols "$T/self/chain.list" | cycles >"$T/self/chain.out"
  rc=$?
  if [ $rc -eq 0 ] && [ ! -s "$T/self/chain.out" ]; then ok
  else bad "self-test: a chain e.c -> d.c reported as a cycle (rc $rc): $(cat "$T/self/chain.out")"; fi
else
  bad "self-test: $CC cannot compile"
fi

# ---- the project's sources and an object for each.
cd "$ROOT" || exit 1
find src analysis baselines python/src -type f \( -name '*.c' -o -name '*.cpp' -o -name '*.cu' \) \
  -not -path '*/tests/*' | LC_ALL=C sort >"$T/sources"
# Nested build trees (the Python package's under BUILD_DIR/python) are
# other configurations: their folders hold a CMakeCache.txt of their own.
find "$B" -mindepth 2 -name CMakeCache.txt -printf '%h\n' >"$T/nested"
find "$B" -name '*.o' -path '*/CMakeFiles/*.dir/*' | LC_ALL=C sort | while read -r obj; do
  rel=${obj#"$B"/}
  skip=0
  while read -r n; do case "$obj" in "$n"/*) skip=1 ;; esac; done <"$T/nested"
  [ $skip -eq 0 ] || continue
  sub=${rel%%CMakeFiles/*}          # "analysis/" or ""
  path=${rel#*CMakeFiles/*.dir/}    # "farthest.c.o", "__/src/pointfile.c.o"
  path=${path%.o}
  src=$(printf '%s%s\n' "$sub" "$path" | sed 's#__/#../#g')
  src=$(realpath -m --relative-to="$ROOT" "$ROOT/$src")
  [ -f "$src" ] || continue         # an object of a removed source
  [ "$src" -nt "$obj" ] && continue  # stale
  printf '%s %s\n' "$src" "$obj"
done >"$T/objects"

# Sources without an object: compile them here (the Python binding).
# Include path: every folder of the sources that holds a header.
INC=""
for d in $(find src analysis baselines python/src -name '*.h' -o -name '*.hpp' | xargs -n1 dirname | sort -u); do
  INC="$INC -I$ROOT/$d"
done
# The first Python with both: the package's virtual environment (make
# python, or the python test), then the system's.
pyinc="" npinc="" PY=""
for p in "$B/venv/bin/python" python3 /usr/bin/python3; do
  command -v "$p" >/dev/null 2>&1 || continue
  i=$("$p" -c 'import sysconfig; print(sysconfig.get_paths()["include"])' 2>/dev/null)
  n=$("$p" -c 'import numpy; print(numpy.get_include())' 2>/dev/null)
  [ -n "$PY" ] || PY=$p
  if [ -f "$i/Python.h" ] && [ -n "$n" ]; then pyinc=$i npinc=$n PY=$p; break; fi
done
mkdir -p "$T/obj"
unchecked=0
while read -r src; do
  awk -v s="$src" '$1 == s { f = 1 } END { exit !f }' "$T/objects" && continue
  obj="$T/obj/$(printf '%s' "$src" | tr / _).o"
  case "$src" in
    python/src/*)
      if [ -z "$pyinc" ] || [ ! -f "$pyinc/Python.h" ] || [ -z "$npinc" ]; then
        echo "SKIP: $src: no Python.h with NumPy's headers (python3-dev and numpy, e.g. make python): the binding is not checked"
        continue
      fi
      flags="-I$pyinc -I$npinc" ;;
    *.cu)
      echo "SKIP: $src: no object in $B (built only where nvcc exists)"
      continue ;;
    *) flags="" ;;
  esac
  case "$src" in *.cpp) cc=$CXX ;; *) cc=$CC ;; esac
  # shellcheck disable=SC2086
  if "$cc" -c -w -fopenmp $INC $flags -o "$obj" "$src" 2>"$T/cc.err"; then
    printf '%s %s\n' "$src" "$obj" >>"$T/objects"
  else
    unchecked=$((unchecked + 1))
    bad "$src: no object in $B and it does not compile here: $(head -n 3 "$T/cc.err")"
  fi
done <"$T/sources"
[ $unchecked -eq 0 ] && ok

nsrc=$(cut -d' ' -f1 "$T/objects" | sort -u | wc -l)
if symbols "$T/objects" | cycles >"$T/cycles.out"; then ok
else
  if command -v c++filt >/dev/null 2>&1; then c++filt <"$T/cycles.out" >&2; else cat "$T/cycles.out" >&2; fi
  bad "$(grep -c '^cycle:' "$T/cycles.out") call cycle(s) between files (move the shared piece down a layer)"
fi
echo "test_cycles: $nsrc source files checked"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
