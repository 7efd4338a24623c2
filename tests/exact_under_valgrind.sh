#!/bin/sh
# exact_under_valgrind.sh VALGRIND CLASH4D SCENE DIR
# Valgrind rounds every floating-point operation to nearest, whatever the
# rounding mode, so the interval kernel's enclosures do not hold there
# (exact/Interval_kernel.h, encloses_here): exact must then answer in
# rationals alone. Held three ways on a closed touch that hinges on the
# rounding of 1/10: the answer under valgrind is the native one, the run
# says it fell back (exact_fallbacks: 1), and the certificate it writes
# verifies natively.
set -u
valgrind=$1 clash4d=$2 scene=$3 dir=$4
cert="$dir/exact_under_valgrind.cert.json"
rm -f "$cert"
native=$("$clash4d" check --semantics closed "$scene")
under=$("$valgrind" -q --tool=none "$clash4d" check --semantics closed --stats --certificate "$cert" "$scene")
answer=$(printf '%s\n' "$under" | sed '/^stats:/,$d; /^certificate: /d')
if [ "$answer" != "$native" ]; then
  printf 'under valgrind:\n%s\nnative:\n%s\n' "$answer" "$native"
  echo "FAIL: exact's answer under valgrind is not the native one"
  exit 1
fi
if ! printf '%s\n' "$under" | grep -q '^  exact_fallbacks: 1$'; then
  printf '%s\n' "$under"
  echo "FAIL: the run under valgrind did not fall back to rationals"
  exit 1
fi
if ! "$clash4d" verify "$scene" "$cert"; then
  echo "FAIL: the certificate written under valgrind does not verify"
  exit 1
fi
echo "PASS: under valgrind, exact answered in rationals: the native answer, and a certificate that verifies"
