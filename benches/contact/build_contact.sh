#!/usr/bin/env bash
# Builds CONTACT's standalone program with gfortran and reference LAPACK (no Intel compiler, no MKL)
# from a checkout of its public repository, https://github.com/eve70a/CONTACT (checked at commit
# d431cdb). See README.md next to this file for what the patch changes and why.
# Usage: bash benches/contact/build_contact.sh CONTACT_CHECKOUT  ->  CONTACT_CHECKOUT/bin/contact_gf
# Needs gfortran, patch and LAPACK (Debian/Ubuntu: apt-get install gfortran liblapack-dev patch).
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 CONTACT_CHECKOUT" >&2; exit 2; }
top=$(cd "$1" && pwd)
patchfile=$(cd "$(dirname "$0")" && pwd)/contact-gfortran.patch
src=$top/src
[ -f "$src/contact.f90" ] || { echo "$top: no src/contact.f90; is this a CONTACT checkout?" >&2; exit 2; }
stamp=$src/.halfplane-gfortran-patch
if [ ! -e "$stamp" ]; then
    patch -p1 -d "$top" < "$patchfile"
    touch "$stamp"
fi
cd "$src"
mkdir -p obj/gf ../bin
flags="-cpp -O3 -march=native -ffree-line-length-none -fno-range-check -DTARGET_exe -I. -Jobj/gf -Iobj/gf"
# mkl_dfti only declares the FFT interface; m_caddon_data belongs to the library build, not the program.
modules="mkl_dfti $(ls m_*.f90 | sed 's/\.f90$//' | grep -v '^m_caddon_data$')"
# The modules use each other and the sources carry no dependency list: compile in rounds until all
# of them build (each round compiles at least one more, or the build stops with the failing ones).
todo=$modules
while [ -n "$todo" ]; do
    failed=""
    for m in $todo; do
        gfortran -c $flags "$m.f90" -o "obj/gf/$m.o" 2> "obj/gf/$m.err" || failed="$failed $m"
    done
    failed=${failed# }
    if [ "$failed" = "$todo" ]; then
        echo "cannot compile: $failed (messages in $src/obj/gf/*.err)" >&2
        exit 1
    fi
    todo=$failed
done
gfortran $flags contact.f90 $(for m in $modules; do printf 'obj/gf/%s.o ' "$m"; done) -llapack -o ../bin/contact_gf
echo "built $top/bin/contact_gf"
