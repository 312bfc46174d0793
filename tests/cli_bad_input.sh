#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every kind of bad input makes `roughroll` exit 2 with exactly one line on stderr that
# names the problem, and nothing on stdout. Usage: cli_bad_input.sh path/to/roughroll
set -u
# bin, dir, fail, expect NAME KEYWORD -- ARGS..., good_scene, finish (cli_lib.sh); `run_under` runs
# expect as another user (one row below).
source "$(dirname "$0")/cli_lib.sh"

scene() {  # scene NAME CONTENT: writes $dir/NAME.toml
    printf '%s\n' "$2" >"$dir/$1.toml"
}

good=$good_scene
scene good "$good"
scene noQ "$(printf '%s\n' "$good" | grep -v '^Q =')"
scene malformed 'friction = '
scene truncated "$(printf '%s\n' "$good" | head -c 40)"
scene wrongtype 'friction = "high"'
scene unknownkey "$(printf '%s\nfrction = 0.3' "$good")"
scene unknownnested "$(printf '%s\n' "$good" | sed 's/^A = 0.5$/Ax = 0.5/' )"
scene unknowntable "$(printf '%s\n[cylinder3.normal]\nT = 1\nA = 1' "$good")"
scene fzero 'friction = 0.0'
scene fneg 'friction = -0.3'
scene fnan 'friction = nan'
scene Qnan "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = nan/')"
scene Qbig "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = 0.31/')"
scene Tneg "$(printf '%s\n' "$good" | sed '0,/^T = 0.5/s//T = -0.5/')"
scene Ainf "$(printf '%s\n' "$good" | sed '0,/^A = 0.5/s//A = inf/')"
scene Anan "$(printf '%s\n' "$good" | sed '0,/^A = 0.5/s//A = nan/')"
scene nbig "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 100000000/')"
scene nsmall "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 1/')"
scene nfloat "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 20.5/')"
scene method "$(printf '%s\nmethod = "spectral"' "$good")"
scene stiff "$(printf '%s\n' "$good" | sed 's/^A = 0.5$/A = 1000/; s/^n = 20/n = 20\nmethod = "paper"/')"
# The rows of docs/robustness.md that the rows above do not cover.
scene empty ''
printf 'friction = 0.3\n\377\376\000bad\n' >"$dir/binary.toml"
scene unknowntop "$(printf 'frction = 0.3\n%s' "$good")"
scene tabletype "$(printf 'friction = 0.3\ncylinder1 = 3')"
scene Ttype "$(printf '%s\n' "$good" | sed '0,/^T = 0.5/s//T = "0.5"/')"
scene halfterm "$(printf '%s\n' "$good" | sed '0,/^A = 0.5/s///')"
scene finf 'friction = inf'
scene Qinf "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = inf/')"
scene Qhuge "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = 1e308/')"
scene Tnan "$(printf '%s\n' "$good" | sed '0,/^T = 0.5/s//T = nan/')"
scene Aneg "$(printf '%s\n' "$good" | sed '0,/^A = 0.5/s//A = -0.5/')"
scene nwrap "$(printf '%s\n' "$good" | sed 's/^n = 20/n = 4294967316/')"
scene coarse "$(printf '%s\n' "$good" | sed 's/^A = 0.5$/A = 1e308/')"
# A valid scene whose tangential compliance T is so large that the discrete tangential
# system's reciprocal condition number (1.6e-15) is below the guard of linear_system.cpp.
scene singular "$(printf '%s\n' "$good" | sed '0,/^T = 0.5/s//T = 1e15/')"
# Two inputs on which toml++ 3.3.0 breaks its own assumptions (docs/robustness.md): a table
# header whose key starts with '#', and a code point of U+00A1-U+0499 outside a string.
scene hashheader "$(printf '%s\n[#cylinder1]' "$good")"
scene nonascii "$(printf 'friction = 0.3\302\247')"
scene unreadable "$good"
chmod 000 "$dir/unreadable.toml"
: >"$dir/a-file"

expect missing-file "cannot read" -- point "$dir/nope.toml"
expect directory "cannot read" -- point "$dir"
expect malformed-toml "malformed" -- point "$dir/malformed.toml"
expect truncated-toml "malformed" -- point "$dir/truncated.toml"
expect wrong-type "friction" -- point "$dir/wrongtype.toml"
expect unknown-key "frction" -- point "$dir/unknownkey.toml"
expect unknown-nested-key "Ax" -- point "$dir/unknownnested.toml"
expect unknown-table "cylinder3" -- point "$dir/unknowntable.toml"
expect f-zero "friction" -- point "$dir/fzero.toml" --Q 0
expect f-negative "friction" -- point "$dir/fneg.toml" --Q 0
expect f-nan "friction" -- point "$dir/fnan.toml" --Q 0
expect Q-missing "Q" -- point "$dir/noQ.toml"
expect Q-nan-scene "Q" -- point "$dir/Qnan.toml"
expect Q-nan-cli "Q" -- point "$dir/good.toml" --Q nan
expect Q-inf-cli "Q" -- point "$dir/good.toml" --Q inf
expect Q-above-f "slide" -- point "$dir/Qbig.toml"
expect Q-below-minus-f "slide" -- point "$dir/good.toml" --Q -0.3000001
# The ladder's tolerance (problems/level_ladder.hpp): in (0, 1) and finite, as the key and as
# --tolerance, and not beside an n given in the same place (refused before any solve).
scene tolzero "$(printf '%s\n' "$good" | sed 's/^n = 20/tolerance = 0/')"
scene tolbig "$(printf '%s\n' "$good" | sed 's/^n = 20/tolerance = 2/')"
scene tolnan "$(printf '%s\n' "$good" | sed 's/^n = 20/tolerance = nan/')"
scene tolwithn "$(printf '%s\ntolerance = 1e-6' "$good")"
expect tolerance-key-zero "solver.tolerance" -- point "$dir/tolzero.toml"
expect tolerance-key-big "solver.tolerance" -- point "$dir/tolbig.toml"
expect tolerance-key-nan "solver.tolerance" -- point "$dir/tolnan.toml"
expect tolerance-key-with-n "solver.tolerance" -- point "$dir/tolwithn.toml"
expect tolerance-cli-zero "tolerance" -- point "$dir/good.toml" --tolerance 0
expect tolerance-cli-negative "tolerance" -- point "$dir/good.toml" --tolerance -1e-6
expect tolerance-cli-one "tolerance" -- curve "$dir/good.toml" --tolerance 1
expect tolerance-cli-inf "tolerance" -- point "$dir/good.toml" --tolerance inf
expect tolerance-cli-text "--tolerance" -- point "$dir/good.toml" --tolerance abc
expect tolerance-cli-with-n "tolerance" -- point "$dir/good.toml" --tolerance 1e-6 --n 64
# --friction over the scene's: its range as the key's, and the scene's Q (0.15) checked against it.
expect friction-cli-zero "--friction" -- point "$dir/good.toml" --friction 0
expect friction-cli-nan "--friction" -- point "$dir/good.toml" --friction nan
expect friction-cli-huge "--friction" -- point "$dir/good.toml" --friction 1e13
expect friction-cli-text "--friction" -- point "$dir/good.toml" --friction abc
expect friction-cli-below-Q "slide" -- point "$dir/good.toml" --friction 0.1
expect friction-cli-below-Q-traction "slide" -- traction "$dir/good.toml" --friction 0.1 --out "$dir/t" --no-plot
expect T-negative "T" -- point "$dir/Tneg.toml"
expect A-infinite "A" -- point "$dir/Ainf.toml"
expect A-nan "A" -- point "$dir/Anan.toml"
expect n-huge "n" -- point "$dir/nbig.toml"
expect n-small "n" -- point "$dir/nsmall.toml"
expect n-float "n" -- point "$dir/nfloat.toml"
expect n-cli "outside" -- point "$dir/good.toml" --n 5000
expect n-cli-negative "outside" -- point "$dir/good.toml" --n -3
expect method-scene "spectral" -- point "$dir/method.toml"
expect method-cli "spectral" -- point "$dir/good.toml" --method spectral
expect beyond-resolution "resolution" -- point "$dir/stiff.toml"
expect curve-points "points" -- curve "$dir/good.toml" --points 1
expect curve-unwritable "cannot write" -- curve "$dir/good.toml" --points 3 --csv "$dir/no/such/dir/x.csv"
expect unknown-option "--frobnicate" -- point "$dir/good.toml" --frobnicate
expect no-subcommand "subcommand" --
expect figure-unknown "2c" -- figure 2c

# Files.
expect not-regular-file "not a regular file" -- point /dev/null
expect empty-file "missing key 'friction'" -- point "$dir/empty.toml"
expect invalid-utf8 "malformed" -- point "$dir/binary.toml"
expect table-header-hash "malformed" -- point "$dir/hashheader.toml"
expect non-ascii-outside-string "malformed" -- point "$dir/nonascii.toml"
# root reads any file: that row runs as nobody when setpriv can run the program so.
if [ "$(id -u)" -ne 0 ]; then
    expect unreadable-file "Permission denied" -- point "$dir/unreadable.toml"
elif chmod 711 "$dir" && setpriv --reuid=65534 --regid=65534 --clear-groups "$bin" --help >/dev/null 2>&1; then
    run_under=(setpriv --reuid=65534 --regid=65534 --clear-groups)
    expect unreadable-file "Permission denied" -- point "$dir/unreadable.toml"
    run_under=()
else
    echo "skip unreadable-file: running as root and cannot run $bin as nobody"
fi

# Keys, tables and types.
expect unknown-key-top "unknown key 'frction'" -- point "$dir/unknowntop.toml"
expect wrong-type-table "must be a table" -- point "$dir/tabletype.toml"
expect wrong-type-T "must be a number, not a string" -- point "$dir/Ttype.toml"
expect term-missing-A "needs both T and A" -- point "$dir/halfterm.toml"

# Values.
expect f-inf "friction" -- point "$dir/finf.toml" --Q 0
expect Q-inf-scene "must be finite" -- point "$dir/Qinf.toml"
expect Q-huge-scene "slide" -- point "$dir/Qhuge.toml"
expect T-nan "must be finite and >= 0" -- point "$dir/Tnan.toml"
expect A-negative "must be finite and >= 0" -- point "$dir/Aneg.toml"
expect n-wraps-int "4294967316 is outside" -- point "$dir/nwrap.toml"

# Command-line options.
expect Q-cli-text "--Q" -- point "$dir/good.toml" --Q abc
expect n-cli-zero "outside" -- point "$dir/good.toml" --n 0
expect n-cli-overflow "--n" -- point "$dir/good.toml" --n 99999999999
expect curve-points-text "--points" -- curve "$dir/good.toml" --points x
expect traction-points-few "--points" -- traction "$dir/good.toml" --points 2 --out "$dir/t" --no-plot
expect traction-points-many "--points" -- traction "$dir/good.toml" --points 1000000 --out "$dir/t" --no-plot
expect traction-out-file "cannot create output folder" -- traction "$dir/good.toml" --out "$dir/a-file" --no-plot
expect name-slash "is not a file name" -- traction "$dir/good.toml" --name a/b --out "$dir/t" --no-plot
expect name-control "a\\x0ab" -- traction "$dir/good.toml" --name "$(printf 'a\nb')" --out "$dir/t" --no-plot
expect name-dotdot "is not a file name" -- traction "$dir/good.toml" --name .. --out "$dir/t" --no-plot
expect convergence-Q-zero "nothing to converge" -- convergence "$dir/good.toml" --Q 0 --out "$dir/t" --no-plot
expect convergence-max-seconds "--max-seconds" -- convergence "$dir/good.toml" --max-seconds -1 --no-plot
expect figure-points "points" -- figure 2a --points 1 --out "$dir/t" --no-plot
expect figure-n-too-large "2n <= 1000" -- figure 2a --n 501 --points 2 --out "$dir/t" --no-plot

# Numerical faults a valid scene can reach.
expect extrapolated-coarse-level "n/2" -- point "$dir/coarse.toml"
expect singular-system "singular" -- point "$dir/singular.toml"
# Findings of docs/robustness.md, closed: a load too small against f for double precision,
# an infinite creep at the gross-sliding shortcut.
expect load-below-precision "relative precision" -- point "$dir/good.toml" --Q 1e-12
scene hugefriction "$(printf '%s\n' "$good" | sed 's/^friction = 0.3/friction = 1e12/')"
expect huge-friction "relative precision" -- point "$dir/hugefriction.toml"
scene hugeT "$(printf 'friction = 0.3\n[cylinder1.tangential]\nT = 1e308\nA = 0.5\n')"
expect infinite-creep "not finite" -- point "$dir/hugeT.toml" --Q 0.3

# Physical scenes (SI units): materials, radii, loads, stiffness k, t.
phys='E = 210e9
nu = 0.3
R1 = 0.02
R2 = 0.02
P2 = 1e5
P1 = 1.5e4
friction = 0.3
[cylinder1.tangential]
k = 4e14
t = 1.5e6
[solver]
n = 32'
scene phys "$phys"
scene physnoR2 "$(printf '%s\n' "$phys" | grep -v '^R2 =')"
scene physnu "$(printf '%s\n' "$phys" | sed 's/^nu = 0.3/nu = 0.7/')"
scene physE "$(printf '%s\n' "$phys" | sed 's/^E = 210e9/E = -1/')"
scene physR "$(printf '%s\n' "$phys" | sed 's/^R1 = 0.02/R1 = 0/')"
scene physplanes "$(printf '%s\n' "$phys" | sed 's/^R1 = 0.02/R1 = inf/; s/^R2 = 0.02/R2 = inf/')"
scene physP2 "$(printf '%s\n' "$phys" | sed 's/^P2 = 1e5/P2 = nan/')"
scene physP1 "$(printf '%s\n' "$phys" | sed 's/^P1 = 1.5e4/P1 = 3.1e4/')"
scene physP1Q "$(printf 'Q = 0.1\n%s\n' "$phys")"
scene physhertzP1 "$(printf 'contact_width = "hertz"\n%s\n' "$phys")"
scene physwidth "$(printf 'contact_width = "wide"\n%s\n' "$phys")"
scene physt0 "$(printf '%s\n' "$phys" | sed 's/^t = 1.5e6/t = 0/')"
scene physk "$(printf '%s\n' "$phys" | sed 's/^k = 4e14/k = -4e14/')"
scene physhalf "$(printf '%s\n' "$phys" | sed 's/^k = 4e14//')"
scene physmix "$(printf '%s\n' "$phys" | sed 's/^k = 4e14/T = 0.5/')"
scene ktnophys "$(printf 'friction = 0.3\nQ = 0.1\n[cylinder1.normal]\nk = 1e14\nt = 1e6\n')"
expect physical-missing-R2 "missing 'R2'" -- point "$dir/physnoR2.toml"
expect physical-nu-range "'nu' must be in (-1, 0.5]" -- point "$dir/physnu.toml"
expect physical-E-negative "'E' must be finite and > 0" -- point "$dir/physE.toml"
expect physical-R-zero "'R1' must be > 0" -- point "$dir/physR.toml"
expect physical-two-planes "two planes" -- point "$dir/physplanes.toml"
expect physical-P2-nan "'P2' must be finite and > 0" -- point "$dir/physP2.toml"
expect physical-P1-slides "|P1| <= f P2" -- point "$dir/physP1.toml"

# Dissimilar rollers (docs/formulation.md 8): a material per cylinder, beta_d, coupling.
pair='R1 = 0.05
R2 = 0.05
P2 = 1e5
Q = 0.0
friction = 0.05
[cylinder1]
shear_modulus = 23e9
poisson = 0.31
[cylinder2]
shear_modulus = 82e9
poisson = 0.28'
scene pairnu "$(printf '%s\n' "$pair" | sed 's/^poisson = 0.31/poisson = 0.6/')"
scene pairnulow "$(printf '%s\n' "$pair" | sed 's/^poisson = 0.28/poisson = -1/')"
scene pairmu "$(printf '%s\n' "$pair" | sed 's/^shear_modulus = 82e9/shear_modulus = 0/')"
scene pairhalf "$(printf '%s\n' "$pair" | sed 's/^poisson = 0.28//')"
scene pairone "$(printf '%s\n' "$pair" | sed '/^\[cylinder2\]/,$d')"
scene pairE "$(printf 'E = 210e9\n%s\n' "$pair")"
scene pairbeta "$(printf 'beta_d = 0.1\n%s\n' "$pair")"
scene pairnoP2 "$(printf '%s\n' "$pair" | grep -v '^P2 =')"
scene mudimless "$(printf 'friction = 0.3\nQ = 0.1\n[cylinder1]\nshear_modulus = 1e9\npoisson = 0.3\n')"
scene betabig "$(printf 'beta_d = 0.75\n%s\n' "$good")"
scene betanan "$(printf 'beta_d = nan\n%s\n' "$good")"
scene betatype "$(printf 'beta_d = "0.1"\n%s\n' "$good")"
scene coupling "$(printf 'coupling = "strong"\n%s\n' "$good")"
scene couplingtype "$(printf 'coupling = 1\n%s\n' "$good")"
scene pairfull "$(printf 'coupling = "full"\n%s\n' "$pair")"
scene betaoneparam "$(printf 'beta_d = 0.1\ncoupling = "full"\n%s\nmethod = "one-parameter"\n' "$good")"
scene betasingle "$(printf 'beta_d = 0.1\n%s\nzones = "single"\n' "$good")"
expect pair-poisson-range "'cylinder1.poisson' must be in (-1, 0.5]" -- point "$dir/pairnu.toml"
expect pair-poisson-minus-one "'cylinder2.poisson' must be in (-1, 0.5]" -- point "$dir/pairnulow.toml"
expect pair-shear-modulus "'cylinder2.shear_modulus' must be finite and > 0" -- point "$dir/pairmu.toml"
expect pair-half-material "needs both shear_modulus and poisson (missing 'poisson')" -- point "$dir/pairhalf.toml"
expect pair-one-cylinder "missing in 'cylinder2'" -- point "$dir/pairone.toml"
expect pair-and-E "not both: remove 'E'" -- point "$dir/pairE.toml"
expect pair-beta-key "'beta_d' is not a key of a physical scene" -- point "$dir/pairbeta.toml"
expect pair-missing-P2 "needs R1, R2 and P2: missing 'P2'" -- point "$dir/pairnoP2.toml"
expect material-needs-physical "'cylinder1.shear_modulus' needs a physical scene" -- point "$dir/mudimless.toml"
expect beta-d-bound "|beta_d| < 0.75" -- point "$dir/betabig.toml"
expect beta-d-nan "beta_d = nan must be finite" -- point "$dir/betanan.toml"
expect beta-d-type "'beta_d' must be a number" -- point "$dir/betatype.toml"
expect coupling-unknown "unknown coupling 'strong'" -- point "$dir/coupling.toml"
expect coupling-type "toml: 'coupling' must be a string" -- point "$dir/couplingtype.toml"
# A physical scene at full coupling settles a width per load (the curve's rows too): a swept curve
# (continued in the load at Johnson's level only) is refused, before any width is searched.
expect coupling-full-physical-sweep 'solve the curve without --sweep (Python sweep=False: --points loads from -f to f, the same rows), or set coupling = "johnson"' -- curve "$dir/pairfull.toml" --sweep --points 3
expect beta-one-parameter "only Johnson's level is derived for the one-parameter limit" -- point "$dir/betaoneparam.toml"
expect beta-zones-single "zones 'single' with beta_d != 0" -- point "$dir/betasingle.toml"
scene betafull "$(printf 'friction = 0.05\nbeta_d = 0.14\ncoupling = "full"\nQ = 0.0\n[solver]\nn = 32\nmethod = "product"\n')"
expect beta-full-sweep "is continued in the load at Johnson's level only" -- curve "$dir/betafull.toml" --sweep --points 3
# (A zone below the resolution is refused only after a solve: validate_five_zone_points tests it,
# without a wall-clock limit. Every row here is refused before any solve.)
# "increase n" only where a larger n can help (issue 23): kernels that no n up to 1000 resolves at n/2.
scene steepall "$(printf 'friction = 0.3\nQ = 0.15\n[cylinder1.normal]\nT = 1\nA = 100000\n[solver]\nn = 1000\n')"
expect extrapolated-beyond-every-n "use method 'product' (no n up to 1000 resolves them at n/2)" -- point "$dir/steepall.toml"
# (At an explicit n: without one the ladder takes that advice itself, answering at n = 256: cli_ladder.sh.)
scene steep "$(printf 'friction = 0.3\nQ = 0.15\n[cylinder1.normal]\nT = 1\nA = 300\n[solver]\nn = 128\n')"
expect extrapolated-larger-n "increase n (at most 1000) or use method 'product'" -- point "$dir/steep.toml"
expect physical-P1-and-Q "not both" -- point "$dir/physP1Q.toml"
expect physical-P1-hertz-width "given-load" -- point "$dir/physhertzP1.toml"
expect physical-width-rule "contact_width" -- point "$dir/physwidth.toml"
expect physical-t-zero "one-parameter" -- point "$dir/physt0.toml"
expect physical-k-negative "'cylinder1.tangential.k' must be finite and >= 0" -- point "$dir/physk.toml"
expect physical-term-half "needs both k and t" -- point "$dir/physhalf.toml"
expect physical-term-mixed "unknown key 'cylinder1.tangential.T'" -- point "$dir/physmix.toml"
expect k-t-without-physical "need a physical scene" -- point "$dir/ktnophys.toml"
scene physlayerbad "$(printf '%s\n[cylinder2.micro_geometry]\nlambda0 = 1.2e11\nmu0 = 8e10\nH = 1e-5\nl = 1e-4\nprofile = "sine"\ndelta = 2e-5\ndecay = "linear"\n' "$(printf '%s\n' "$phys" | grep -v '^n = 32' | grep -v '^\[solver\]')")"
scene physlayercsv "$(printf '%s\n[cylinder2.micro_geometry]\nlambda0 = 1.2e11\nmu0 = 8e10\nH = 1e-5\nl = 1e-4\nprofile = "measured"\nprofile_csv = "nope.csv"\ndecay = "linear"\n' "$(printf '%s\n' "$phys" | grep -v '^n = 32' | grep -v '^\[solver\]')")"
expect physical-layer-delta-above-H "delta" -- point "$dir/physlayerbad.toml"
expect physical-layer-csv-missing "nope.csv" -- point "$dir/physlayercsv.toml"
# A contact not small against the radius: (3.7)'s half-spaces do not apply.
scene phystinyR "$(printf '%s\n' "$phys" | sed 's/^R1 = 0.02/R1 = 1e-12/')"
expect physical-width-above-radius "a << R" -- point "$dir/phystinyR.toml"
# A width search that reaches beyond the method's resolution names the trial width.
scene physsoft "$(printf '%s\n' "$phys" | sed 's/^k = 4e14/k = 1e9/; s/^t = 1.5e6/t = 1/; s/^\[cylinder1.tangential\]/[cylinder1.normal]/')"
expect physical-width-beyond-resolution "contact width search at a =" -- point "$dir/physsoft.toml"
# The one-parameter limit needs A > 0 wherever T > 0 (2T/A^2 finite).
scene Azero "$(printf 'friction = 0.3\nQ = 0.1\n[cylinder1.normal]\nT = 0.5\nA = 0\n')"
expect one-parameter-A-zero "no one-parameter limit" -- point "$dir/Azero.toml" --method one-parameter
if ! "$bin" point "$dir/phys.toml" --json >"$dir/out" 2>"$dir/err" || ! grep -q '"xi1"' "$dir/out"; then
    echo "FAIL the valid physical scene did not solve:"; cat "$dir/err"; failures=$((failures + 1))
fi

# Issue 11, section 2: the defects of an adversarial pass, each row failing before its fix.
# Non-finite results from finite input: every derived quantity checked where it is made,
# naming the keys. (Before: exit 0 with xi1 = -nan; "increase n"; T = inf.)
scene physEbig "$(printf '%s\n' "$phys" | sed 's/^E = 210e9/E = 1e300/; s/^R1 = 0.02/R1 = 1e-300/; s/^R2 = 0.02/R2 = 1e-300/; s/^P2 = 1e5/P2 = 1e-300/; s/^P1 = 1.5e4/Q = 0.1/')"
expect physical-hertz-width-underflow "Hertz half-width a_H of (3.27) = 0 (E = 1e+300 Pa, nu = 0.3, R = 5e-301 m, P = 1e-300 N/m) is beyond double precision: check 'E', 'R1', 'R2' and 'P2'" -- point "$dir/physEbig.toml"
scene physP2denormal "$(printf '%s\n' "$phys" | sed 's/^P2 = 1e5/P2 = 5e-324/; s/^P1 = 1.5e4/Q = 0.1/')"
expect physical-P2-subnormal "'P2' = 5e-324 is below 2.2250738585072014e-308, the smallest normal double" -- point "$dir/physP2denormal.toml"
scene physttiny "$(printf '%s\n' "$phys" | sed 's/^t = 1.5e6/t = 1e-320/')"
expect physical-t-subnormal "'cylinder1.tangential.t' = 1e-320 is below" -- point "$dir/physttiny.toml"
scene physTinf "$(printf '%s\n' "$phys" | sed 's/^t = 1.5e6/t = 1e-305/')"
expect physical-T-overflow "T = a mu/(8 (1 - nu) t) of (3.26) = inf" -- point "$dir/physTinf.toml"
expect physical-T-overflow-names-t "check 'cylinder1.tangential.t' and 'E'" -- point "$dir/physTinf.toml"
scene physTgiven "$(printf '%s\n' "$phys" | sed 's/^k = 4e14/T = 1e-305/; s/^t = 1.5e6/A = 0.5/')"
expect physical-t-from-T-overflow "'cylinder1.tangential': t = a mu/(8 (1 - nu) T) of (3.26) = inf" -- point "$dir/physTgiven.toml"
# A contact far wider than its radius: the a/R refusal before any solve, not resolution advice.
scene physwide "$(printf '%s\n' "$phys" | sed 's/^R1 = 0.02/R1 = 1e-5/; s/^k = 4e14/k = 1e9/; s/^t = 1.5e6/t = 1/; s/^\[cylinder1.tangential\]/[cylinder1.normal]/')"
expect physical-wide-refused-before-search "the Hertz half-width a_H = " -- point "$dir/physwide.toml"
expect physical-wide-names-radius "a << R" -- point "$dir/physwide.toml"
# a_H within R/10 but the width that carries P2 beyond it: the search stops at R/10.
scene physwider "$(printf '%s\n' "$phys" | sed 's/^R1 = 0.02/R1 = 0.005/; s/^k = 4e14/k = 1e9/; s/^t = 1.5e6/t = 1/; s/^\[cylinder1.tangential\]/[cylinder1.normal]/')"
expect physical-wide-found-by-search "the half-width that carries P2 is above a = 4e-04 m, 0.1 times the radius" -- point "$dir/physwider.toml"
# One underflow rule: a nonzero literal below DBL_MIN is refused (scene, CSV, command line).
scene Qunder "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = 1e-400/')"
expect Q-underflow-scene "Qunder.toml:2:5: 'Q' = 1e-400 is below 2.2250738585072014e-308" -- point "$dir/Qunder.toml"
scene fdenormal "$(printf '%s\n' "$good" | sed 's/^friction = 0.3/friction = 1e-310/')"
expect friction-subnormal "'friction' = 1e-310 is below" -- point "$dir/fdenormal.toml"
scene zeros "$(printf '%s\n' "$good" | sed 's/^Q = 0.15/Q = 0.0e-400/')"
if ! "$bin" point "$dir/zeros.toml" >/dev/null 2>"$dir/err"; then
    echo "FAIL a zero written as 0.0e-400 is 0, not an underflow:"; cat "$dir/err"; failures=$((failures + 1))
fi
expect Q-underflow-cli "--Q: 1e-400 is below" -- point "$dir/good.toml" --Q 1e-400
expect Q-subnormal-cli "--Q: 1e-310 is below" -- point "$dir/good.toml" --Q 1e-310
expect Q-overflow-cli "--Q: 1e400 is beyond" -- point "$dir/good.toml" --Q 1e400
mkdir -p "$dir/csvunder"
printf 'lambda0 = 1.15e11\nmu0 = 7.7e10\nH = 1e-5\nl = 4e-5\nprofile = "measured"\nprofile_csv = "p.csv"\ndecay = "linear"\n' >"$dir/csvunder/spec.toml"
printf 'x1,h0\n0,1e-6\n1e-5,1e-400\n2e-5,3e-6\n3e-5,2e-6\n' >"$dir/csvunder/p.csv"
expect csv-underflow "p.csv:3: h0 = 1e-400 is below 2.2250738585072014e-308" -- roughness "$dir/csvunder/spec.toml"
# A spline overshoot in the last piece, which wraps round to x1 = 0: its lines are the last
# sample's and the first's (before: "the closing point x1 = l", a line the file did not have).
mkdir -p "$dir/csvwrap"
cp "$dir/csvunder/spec.toml" "$dir/csvwrap/spec.toml"
printf 'x1,h0\n0,0\n1e-5,5e-6\n2e-5,5e-6\n3e-5,0\n' >"$dir/csvwrap/p.csv"
expect csv-overshoot-wraps "between line 5 and line 2 one period on" -- roughness "$dir/csvwrap/spec.toml"
# Friction outside the validated range [1e-12, 1e12] (before: no input named, or xi/f wrong).
scene fmax "$(printf '%s\n' "$good" | sed 's/^friction = 0.3/friction = 1.79e308/; s/^Q = 0.15/Q = 1e308/')"
expect friction-huge "'friction' = 1.79e+308 is outside [1e-12, 1e+12]" -- point "$dir/fmax.toml"
scene fmin "$(printf '%s\n' "$good" | sed 's/^friction = 0.3/friction = 1e-13/; s/^Q = 0.15/Q = 5e-14/')"
expect friction-tiny "'friction' = 1e-13 is outside [1e-12, 1e+12]" -- point "$dir/fmin.toml"
# Empty option values are errors, not ignored.
expect Q-cli-empty "--Q: '' is not a number" -- point "$dir/good.toml" --Q ""
expect n-cli-empty "--n: '' is not an integer" -- point "$dir/good.toml" --n ""
# A 1 MB key is echoed cut, not whole.
{ printf '%s\n' "$good"; printf '%s = 1\n' "$(head -c 1000000 /dev/zero | tr '\0' k)"; } >"$dir/bigkey.toml"
expect key-echo-cut "kkkkkkkkkk..." -- point "$dir/bigkey.toml"
[ "$(wc -c <"$dir/err")" -lt 300 ] || fail "key-echo-cut: $(wc -c <"$dir/err") bytes on stderr"
# traction's default name is the scene file's: a bad one is blamed on the file, not on --name.
printf '%s\n' "$good" >"$dir/$(printf 'a\nb').toml"
expect traction-scene-name "the scene file's name 'a\x0ab' cannot name the output files" -- traction "$dir/$(printf 'a\nb').toml" --out "$dir/t" --no-plot

# Bytes that are not UTF-8 in a file name: JSON gets \xNN, not exit 70; the terminal never
# gets the raw byte.
"$bin" point "$dir/$(printf 'bad\377name').toml" >"$dir/out" 2>"$dir/err"
if [ $? -ne 2 ] || ! grep -qF 'bad\xffname' "$dir/err" || LC_ALL=C grep -q "$(printf '\377')" "$dir/err"; then
    echo "FAIL non-utf8-in-message: the byte reached stderr raw:"; cat -v "$dir/err"; failures=$((failures + 1))
fi
mkdir -p "$dir/spec"
printf 'lambda0 = 1.15e11\nmu0 = 7.7e10\nH = 1e-5\nl = 1e-4\nprofile = "flat"\ndecay = "linear"\n' >"$dir/spec/$(printf 'flat\377').toml"
for mode in --json text; do
    # JSON escapes the backslash of \xff once more.
    args=(roughness "$dir/spec/$(printf 'flat\377').toml") shown='flat\xff'
    [ "$mode" = --json ] && args+=(--json) && shown='flat\\xff'
    "$bin" "${args[@]}" >"$dir/out" 2>"$dir/err"
    status=$?
    if [ $status -ne 0 ] || ! grep -qF "$shown" "$dir/out" || LC_ALL=C grep -q "$(printf '\377')" "$dir/out"; then
        echo "FAIL non-utf8-spec-name ($mode): status $status"; cat -v "$dir/err"; failures=$((failures + 1))
    else
        echo "ok   non-utf8-spec-name ($mode): the name printed as flat\\xff"
    fi
done

# Writes are checked: a full device is an error with its reason (before: exit 0).
expect_full() {  # expect_full NAME -- ARGS: stdout to /dev/full, exit 2, one line with the reason
    stdout_to=/dev/full expect "$1" "No space left on device" "${@:2}"
}
expect_full point-stdout-full -- point "$dir/good.toml"
expect_full point-json-stdout-full -- point "$dir/good.toml" --json
expect_full curve-stdout-full -- curve "$dir/good.toml" --points 3
expect_full roughness-stdout-full -- roughness "$dir/spec/$(printf 'flat\377').toml"
expect curve-csv-full "cannot write '/dev/full': No space left on device" -- curve "$dir/good.toml" --points 3 --csv /dev/full
expect curve-unwritable-reason "x.csv': No such file or directory" -- curve "$dir/good.toml" --points 3 --csv "$dir/no/such/dir/x.csv"
expect curve-parent-is-file "cannot write '$dir/a-file/x.csv': Not a directory" -- curve "$dir/good.toml" --points 3 --csv "$dir/a-file/x.csv"

# Data loss: a write that fails midway (here the file size limit, as a full disk would)
# leaves the existing file as it was and no temporary file; no 0-byte traction CSV.
mkdir -p "$dir/keep"
printf 'old\n' >"$dir/keep/old.csv"
(trap '' XFSZ; ulimit -f 1; exec "$bin" curve "$dir/good.toml" --points 200 --csv "$dir/keep/old.csv") >"$dir/out" 2>"$dir/err"
status=$?
if [ $status -ne 2 ] || ! grep -qF "File too large" "$dir/err" || [ "$(cat "$dir/keep/old.csv")" != old ] ||
    [ "$(ls -A "$dir/keep")" != old.csv ]; then
    echo "FAIL curve-csv-fails-midway: status $status, $(cat "$dir/err"), left: $(ls -A "$dir/keep" | tr '\n' ' ')"
    failures=$((failures + 1))
else
    echo "ok   curve-csv-fails-midway: $(cat "$dir/err"); old.csv intact, no temporary file"
fi
(trap '' XFSZ; ulimit -f 1; exec "$bin" traction "$dir/good.toml" --out "$dir/traction-full" --no-plot) >"$dir/out" 2>"$dir/err"
status=$?
if [ $status -ne 2 ] || ! grep -qF "File too large" "$dir/err" || [ -n "$(ls -A "$dir/traction-full")" ]; then
    echo "FAIL traction-fails-midway: status $status, $(cat "$dir/err"), left: $(ls -A "$dir/traction-full" | tr '\n' ' ')"
    failures=$((failures + 1))
else
    echo "ok   traction-fails-midway: $(cat "$dir/err"); nothing left in the folder"
fi
cp "$dir/good.toml" "$dir/S.toml"
expect curve-csv-is-input "is the input file" -- curve "$dir/S.toml" --points 3 --csv "$dir/S.toml"
cmp -s "$dir/good.toml" "$dir/S.toml" || fail "curve-csv-is-input: the scene was changed"
mkdir -p "$dir/tin"
cp "$dir/good.toml" "$dir/tin/traction-x.csv"
expect traction-csv-is-input "is the input file" -- traction "$dir/tin/traction-x.csv" --name x --out "$dir/tin" --no-plot

# gnuplot injection: a newline in --out ends gnuplot's command, and the text after it would
# run; control characters are refused and nothing runs (before: the `system` line ran).
pwned="$dir/pwned"
hostile="$(printf 'o\nsystem "touch %s"\n#' "$pwned")"
expect traction-out-newline "holds a control character" -- traction "$dir/good.toml" --points 5 --out "$dir/$hostile"
expect convergence-out-newline "holds a control character" -- convergence "$dir/good.toml" --out "$dir/$hostile" --no-plot
expect figure-out-newline "holds a control character" -- figure 2a --points 2 --out "$dir/$hostile" --no-plot
[ ! -e "$pwned" ] || fail "gnuplot-injection: the system line ran"
# Quotes, a backquote (gnuplot runs `...` even inside a double-quoted title), @ and $( ) in
# a scene file name: plotted as text, nothing runs.
if command -v gnuplot >/dev/null; then
    mkdir -p "$dir/hostile"
    weird="it's \`touch pwned\` @x \$(touch pwned) \"q\""
    printf '%s\n' "$good" >"$dir/hostile/$weird.toml"
    # Run in $dir: a command that ran would leave $dir/pwned.
    if (cd "$dir" && "$bin" traction "hostile/$weird.toml" --points 5 --out hostile/out) >/dev/null 2>"$dir/err" &&
        [ ! -e "$pwned" ] && [ -s "$dir/hostile/out/traction-$weird.svg" ] &&
        [ "$(ls -A "$dir/hostile/out" | grep -c tmp)" -eq 0 ]; then
        echo "ok   gnuplot-hostile-name: plotted, nothing ran"
    else
        echo "FAIL gnuplot-hostile-name: $(cat "$dir/err"); pwned: $([ -e "$pwned" ] && echo yes || echo no)"
        failures=$((failures + 1))
    fi
else
    echo "skip gnuplot-hostile-name: no gnuplot"
fi

# convergence: a smooth scene is refused with the reason, in one line; outputs are checked
# before any work (a scene the solver refuses shows which comes first).
scene smoothscene 'friction = 0.3
Q = 0.1'
expect convergence-smooth "the scene is smooth" -- convergence "$dir/smoothscene.toml" --out "$dir/t"
expect convergence-out-checked-first "cannot create output folder" -- convergence "$dir/coarse.toml" --out "$dir/a-file"
expect traction-out-checked-first "cannot create output folder" -- traction "$dir/coarse.toml" --out "$dir/a-file"
expect figure-out-checked-first "cannot create output folder" -- figure 2a --method paper --n 2 --out "$dir/a-file"
# gnuplot missing: one line saying so (before: gnuplot's lines and "is gnuplot installed?").
mkdir -p "$dir/nopath"
ln -sf "$(command -v env)" "$dir/nopath/env" 2>/dev/null
run_under=(env PATH="$dir/nopath")
expect gnuplot-missing "gnuplot is not installed" -- traction "$dir/good.toml" --points 5 --out "$dir/t"
run_under=()

# A valid scene must still work (the harness above is not failing everything).
if ! "$bin" point "$dir/good.toml" --json >"$dir/out" 2>"$dir/err" || ! grep -q '"xi"' "$dir/out"; then
    echo "FAIL the valid scene did not solve:"; cat "$dir/err"; failures=$((failures + 1))
fi

finish
