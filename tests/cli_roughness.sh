#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `roughroll roughness SPEC [--json]` on the specs of data/roughness/: the JSON keys, and the
# values of the two closed forms of docs/roughness-parameters.md (flat profile and sine profile,
# linear decay) to 1e-10; then every kind of bad spec or profile CSV: exit 2, one stderr line
# naming the problem, nothing on stdout. Usage: cli_roughness.sh path/to/roughroll
set -u
# bin, data, dir, fail, expect, finish (cli_lib.sh).
source "$(dirname "$0")/cli_lib.sh"

# value FILE KEY: the number of a top-level key of the JSON (two spaces of indentation), or of
# an average (four spaces, inside "averages", the first such block).
value() {
    awk -v key="\"$2\":" '
        $1 == "\"averages\":" { inside = 1 }
        inside && /^  }/ { inside = 0 }
        /^  "/ && $1 == key { v = $2 }
        inside && /^    "/ && $1 == key && !done { v = $2; done = 1 }
        END { sub(/,$/, "", v); print v }' "$1"
}

# near NAME GOT EXPECTED: |got/expected - 1| <= 1e-10.
near() {
    if awk -v g="$2" -v e="$3" 'BEGIN { d = g / e - 1; exit !(g != "" && d <= 1e-10 && d >= -1e-10) }'; then
        echo "ok   $1 = $2 (closed form $3)"
    else
        fail "$1 = '$2', closed form $3"
    fi
}

# Flat profile, linear decay (lambda0 = 1.15e11, mu0 = 7.7e10, H = 1e-5):
#   k1 = mu0/H, k2 = (lambda0 + 2 mu0)/H, t1 = (lambda0 + 2 mu0) H/6, t2 = mu0 H/6, <a> = H/3.
if "$bin" roughness "$data/roughness/flat-linear.toml" --json >"$dir/flat.json" 2>"$dir/err"; then
    for key in k_tangential k_normal t_tangential t_normal alpha_tangential alpha_normal averages \
               error_estimate a a3_h1 a33 a_h1 a_h1_squared evaluations; do
        grep -q "\"$key\":" "$dir/flat.json" || fail "flat-linear --json has no key '$key'"
    done
    f=$dir/flat.json
    near k_tangential "$(value "$f" k_tangential)" "$(awk 'BEGIN { print 7.7e10 / 1e-5 }')"
    near k_normal "$(value "$f" k_normal)" "$(awk 'BEGIN { print (1.15e11 + 1.54e11) / 1e-5 }')"
    near t_tangential "$(value "$f" t_tangential)" "$(awk 'BEGIN { printf "%.17g", (1.15e11 + 1.54e11) * 1e-5 / 6 }')"
    near t_normal "$(value "$f" t_normal)" "$(awk 'BEGIN { printf "%.17g", 7.7e10 * 1e-5 / 6 }')"
    near alpha_tangential "$(value "$f" alpha_tangential)" "$(awk 'BEGIN { printf "%.17g", sqrt(7.7e10 / 1e-5 / (2 * 2.69e11 * 1e-5 / 6)) }')"
    near "<a>" "$(value "$f" a)" "$(awk 'BEGIN { printf "%.17g", 1e-5 / 3 }')"
else
    fail "flat-linear: status $?: $(cat "$dir/err")"
fi

# Sine profile (delta = 4e-6), linear decay: A = 1 - delta/(2H), B = delta/(2H),
#   <a> = (H/3)(A^3 + 3/2 A B^2), <a h_1> = (H/3) 2 pi (3/2 A^2 B + 3/8 B^3),
#   <a h_1^2> = (H/3) 4 pi^2 (A^3/2 + 9/8 A B^2), <a3 h_1> = -pi A B, <a33> = A/H.
if "$bin" roughness "$data/roughness/sine-linear.toml" --json >"$dir/sine.json" 2>"$dir/err"; then
    f=$dir/sine.json
    closed=$(awk 'BEGIN {
        pi = atan2(0, -1); H = 1e-5; B = 4e-6 / (2 * H); A = 1 - B; mu = 7.7e10; lam = 1.15e11
        a = H / 3 * (A^3 + 1.5 * A * B^2); ah = H / 3 * 2 * pi * (1.5 * A^2 * B + 0.375 * B^3)
        ahh = H / 3 * 4 * pi^2 * (0.5 * A^3 + 1.125 * A * B^2); a3h = -pi * A * B; a33 = A / H
        c = lam / (lam + 2 * mu)   # the derived factor of (2.12), docs/formulation.md E11
        k1 = mu * (a33 - a3h^2 / ahh); k2 = (lam + 2 * mu) * (a33 - c^2 * a3h^2 / ahh)
        t1 = (lam + 2 * mu) / 2 * (a - ah^2 / ahh); t2 = mu / 2 * (a - ah^2 / ahh)
        printf "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", k1, k2, t1, t2, sqrt(k1 / (2 * t1)), sqrt(k2 / (2 * t2)), a3h, ahh }')
    read -r k1 k2 t1 t2 al1 al2 a3h ahh <<<"$closed"
    near "sine k_tangential" "$(value "$f" k_tangential)" "$k1"
    near "sine k_normal" "$(value "$f" k_normal)" "$k2"
    near "sine t_tangential" "$(value "$f" t_tangential)" "$t1"
    near "sine t_normal" "$(value "$f" t_normal)" "$t2"
    near "sine alpha_tangential" "$(value "$f" alpha_tangential)" "$al1"
    near "sine alpha_normal" "$(value "$f" alpha_normal)" "$al2"
    near "sine <a3 h_1>" "$(value "$f" a3_h1)" "$a3h"
    near "sine <a h_1^2>" "$(value "$f" a_h1_squared)" "$ahh"
else
    fail "sine-linear: status $?: $(cat "$dir/err")"
fi

# The measured example and the text output: k and t positive, units printed.
if "$bin" roughness "$data/roughness/ground-measured.toml" >"$dir/ground.txt" 2>"$dir/err"; then
    for unit in "Pa/m" "Pa m" "1/m" "<a3 h_1>"; do
        grep -qF "$unit" "$dir/ground.txt" || fail "ground-measured text output lacks '$unit'"
    done
    "$bin" roughness "$data/roughness/ground-measured.toml" --json >"$dir/ground.json"
    for key in k_tangential k_normal t_tangential t_normal; do
        awk -v v="$(value "$dir/ground.json" $key)" 'BEGIN { exit !(v > 0) }' || fail "ground-measured $key not > 0"
    done
    echo "ok   ground-measured"
else
    fail "ground-measured: status $?: $(cat "$dir/err")"
fi

# The factor of (2.12) (docs/formulation.md, E11) on every spec of data/roughness/: the default
# is "derived"; with factor_2_12 = "printed" only k_normal and alpha_normal change, and by exactly
#   k_derived - k_printed = mu0 (2 lambda0 + mu0)/(lambda0 + 2 mu0) <a3 h_1>^2/<a h_1^2>
# (to 1e-10), which is 0 for the flat profile. The relative change is printed.
for name in flat-linear sine-linear ground-measured; do
    spec=$data/roughness/$name.toml
    mkdir -p "$dir/factor"
    # The same spec asking for the printed factor, its profile_csv made absolute.
    sed "s|^profile_csv = \"\(.*\)\"|profile_csv = \"$data/roughness/\1\"|" "$spec" >"$dir/factor/$name.toml"
    printf 'factor_2_12 = "printed"\n' >>"$dir/factor/$name.toml"
    if "$bin" roughness "$spec" --json >"$dir/factor/derived.json" 2>"$dir/err" &&
        "$bin" roughness "$dir/factor/$name.toml" --json >"$dir/factor/printed.json" 2>"$dir/err"; then
        d=$dir/factor/derived.json
        p=$dir/factor/printed.json
        grep -q '"factor_2_12": "derived"' "$d" || fail "$name: JSON does not say factor_2_12 derived"
        grep -q '"factor_2_12": "printed"' "$p" || fail "$name: JSON does not say factor_2_12 printed"
        for key in k_tangential t_tangential t_normal; do
            [ "$(value "$d" $key)" = "$(value "$p" $key)" ] || fail "$name: $key changed with the factor of (2.12)"
        done
        kd=$(value "$d" k_normal)
        kp=$(value "$p" k_normal)
        shift=$(awk -v a3h="$(value "$d" a3_h1)" -v ahh="$(value "$d" a_h1_squared)" \
            'BEGIN { lam = 1.15e11; mu = 7.7e10; printf "%.17g", mu * (2 * lam + mu) / (lam + 2 * mu) * a3h^2 / ahh }')
        if awk -v kd="$kd" -v kp="$kp" -v s="$shift" 'BEGIN { d = (kd - kp) - s; exit !(kd != "" && kp != "" && d <= 1e-10 * kd && d >= -1e-10 * kd) }'; then
            echo "ok   $name: k_normal derived $kd, printed $kp Pa/m ($(awk -v kd="$kd" -v kp="$kp" 'BEGIN { printf "%+.3f %%", 100 * (kd / kp - 1) }'))"
        else
            fail "$name: k_normal derived $kd - printed $kp is not $shift"
        fi
    else
        fail "$name with factor_2_12: status $?: $(cat "$dir/err")"
    fi
done

# Bad input. expect NAME KEYWORD -- ARGS...: exit 2, one stderr line containing KEYWORD, empty stdout.

good='lambda0 = 1.15e11
mu0 = 7.7e10
H = 1e-5
l = 1e-4
profile = "sine"
delta = 4e-6
decay = "linear"'
spec() {  # spec NAME CONTENT: writes $dir/NAME.toml
    printf '%s\n' "$2" >"$dir/$1.toml"
}
change() {  # change SED-SCRIPT: the good spec with one change
    printf '%s\n' "$good" | sed "$1"
}
measured='lambda0 = 1.15e11
mu0 = 7.7e10
H = 1e-5
l = 4e-5
profile = "measured"
profile_csv = "p.csv"
decay = "linear"'
csv() {  # csv NAME CONTENT: a folder NAME with the measured spec and its p.csv
    mkdir -p "$dir/$1"
    printf '%s\n' "$measured" >"$dir/$1/spec.toml"
    printf '%s\n' "$2" >"$dir/$1/p.csv"
}

spec malformed 'H = '
spec unknownkey "$(printf '%s\nthickness = 1' "$good")"
spec wrongtype "$(change 's/^H = 1e-5/H = "thin"/')"
spec mu0zero "$(change 's/^mu0 = .*/mu0 = 0/')"
spec Hnan "$(change 's/^H = .*/H = nan/')"
spec linf "$(change 's/^l = .*/l = inf/')"
spec lambdaneg "$(change 's/^lambda0 = .*/lambda0 = -1/')"
spec deltabig "$(change 's/^delta = .*/delta = 1e-5/')"
spec deltaneg "$(change 's/^delta = .*/delta = -1e-6/')"
spec deltaflat "$(change 's/^profile = .*/profile = "flat"/')"
spec deltamissing "$(change '/^delta/d')"
spec profilename "$(change 's/^profile = .*/profile = "wavy"/')"
spec decayname "$(change 's/^decay = .*/decay = "exponential"/')"
spec decaymissing "$(change '/^decay/d')"
spec shapename "$(printf '%s\nmicro_shape = "square"' "$good")"
spec factorname "$(printf '%s\nfactor_2_12 = "paper"' "$good")"
spec csvforsine "$(printf '%s\nprofile_csv = "p.csv"' "$good")"
spec csvmissingkey "$(change 's/^profile = .*/profile = "measured"/; /^delta/d')"
csv csvnofile ''
rm "$dir/csvnofile/p.csv"
csv csvtext 'x1,h0
0,1e-6
1e-5,abc'
csv csvheader 'x,h
0,1e-6'
csv csvfields '0,1e-6,3'
csv csvorder '0,1e-6
2e-5,2e-6
1e-5,2e-6'
csv csvstart '1e-6,1e-6'
csv csvbeyond '0,1e-6
1e-5,2e-6
5e-5,2e-6'
csv csvclosing '0,1e-6
1e-5,2e-6
2e-5,3e-6
3e-5,2e-6
4e-5,2e-6'
csv csvfew '0,1e-6
1e-5,2e-6
2e-5,3e-6'
csv csvnan '0,1e-6
1e-5,nan'
csv csvnegative '0,1e-6
1e-5,-2e-6
2e-5,3e-6
3e-5,2e-6'
csv csvtop '0,1e-6
1e-5,2e-6
2e-5,1e-5
3e-5,2e-6'
# Every sample within [0, H), but the spline through a step dips below 0 beside it.
# Knots 1e-300 m apart: the spline's slopes overflow; a piece of non-finite coefficients must
# not be skipped when the extremes are sought (a fuzz finding: the extremes missed a sample).
csv csvclose '0,1e-6
1e-300,1e-6
2e-300,5e-6
3e-5,2e-6'
csv csvovershoot '0,0
1e-5,0
2e-5,5e-6
3e-5,5e-6'

expect missing-spec "cannot read roughness spec" -- roughness "$dir/nope.toml"
expect directory-spec "it is a directory" -- roughness "$dir"
expect malformed-toml "malformed TOML" -- roughness "$dir/malformed.toml"
expect unknown-key "unknown key 'thickness'" -- roughness "$dir/unknownkey.toml"
expect wrong-type "'H' must be a number, not a string" -- roughness "$dir/wrongtype.toml"
expect mu0-zero "'mu0' must be finite and > 0" -- roughness "$dir/mu0zero.toml"
expect H-nan "'H' must be finite and > 0 (got nan)" -- roughness "$dir/Hnan.toml"
expect l-inf "'l' must be finite and > 0 (got inf)" -- roughness "$dir/linf.toml"
expect lambda0-negative "'lambda0' must be finite and >= 0" -- roughness "$dir/lambdaneg.toml"
expect delta-not-below-H "'delta' = 1e-05 must be < 'H'" -- roughness "$dir/deltabig.toml"
expect delta-negative "'delta' must be finite and >= 0" -- roughness "$dir/deltaneg.toml"
expect delta-for-flat "'delta' is not used by profile = \"flat\"" -- roughness "$dir/deltaflat.toml"
expect delta-missing "missing key 'delta'" -- roughness "$dir/deltamissing.toml"
expect profile-unknown "'profile' must be one of" -- roughness "$dir/profilename.toml"
expect decay-unknown "'decay' must be one of" -- roughness "$dir/decayname.toml"
expect decay-missing "missing key 'decay'" -- roughness "$dir/decaymissing.toml"
expect micro-shape-unknown "'micro_shape' must be one of" -- roughness "$dir/shapename.toml"
expect factor-unknown "'factor_2_12' must be one of \"derived\", \"printed\" (got \"paper\")" -- roughness "$dir/factorname.toml"
expect csv-for-sine "'profile_csv' is not used" -- roughness "$dir/csvforsine.toml"
expect csv-key-missing "missing key 'profile_csv'" -- roughness "$dir/csvmissingkey.toml"
expect csv-missing-file "cannot read profile file" -- roughness "$dir/csvnofile/spec.toml"
expect csv-not-a-number "p.csv:3: h0 'abc' is not a number" -- roughness "$dir/csvtext/spec.toml"
expect csv-bad-header "p.csv:1: x1 'x' is not a number (the only header allowed is 'x1,h0')" -- roughness "$dir/csvheader/spec.toml"
expect csv-three-fields "p.csv:1: expected two comma-separated fields" -- roughness "$dir/csvfields/spec.toml"
expect csv-not-increasing "p.csv:3: x1 = 1e-05 does not increase" -- roughness "$dir/csvorder/spec.toml"
expect csv-not-at-zero "p.csv:1: the first sample must be at x1 = 0" -- roughness "$dir/csvstart/spec.toml"
expect csv-beyond-period "p.csv:3: x1 = 5e-05 is beyond the period" -- roughness "$dir/csvbeyond/spec.toml"
expect csv-closing-point "p.csv:5: the closing point" -- roughness "$dir/csvclosing/spec.toml"
expect csv-too-few "at least 4 samples" -- roughness "$dir/csvfew/spec.toml"
expect csv-nan "p.csv:2: h0 = nan is not finite" -- roughness "$dir/csvnan/spec.toml"
expect csv-negative "p.csv:2: h0 = -2e-06 is below 0" -- roughness "$dir/csvnegative/spec.toml"
expect csv-at-H "p.csv:3: h0 = 1e-05 is not below H" -- roughness "$dir/csvtop/spec.toml"
expect csv-close-knots "is not finite (samples too close together" -- roughness "$dir/csvclose/spec.toml"
expect csv-overshoot "overshoots to h0 = -" -- roughness "$dir/csvovershoot/spec.toml"
expect no-spec "SPEC" -- roughness
expect unknown-option "--frobnicate" -- roughness "$data/roughness/flat-linear.toml" --frobnicate

finish
