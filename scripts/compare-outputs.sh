#!/usr/bin/env bash
# Behaviour unchanged (issue 38): run a fixed set of commands over the shared maps and the tests'
# data and keep what they print and write in OUT, so that two builds' outputs can be compared:
#   scripts/compare-outputs.sh BUILD_DIR OUT        run the set with BUILD_DIR's commands
#   diff -r OUT_BEFORE OUT_AFTER                    (elapsed times and paths are masked)
set -uo pipefail
build=$(cd "$1" && pwd) out=$2
mkdir -p "$out"
out=$(cd "$out" && pwd)
root=$(cd "$(dirname "$0")/.." && pwd)
maps=$root/tests/data/surfaces
asp=$build/asperity tg=$build/apps/tablegen/tablegen
n=0
run() {  # run NAME COMMAND...: stdout, stderr and status kept; times and the output folder masked
  n=$((n + 1))
  local name=$1
  shift
  (cd "$out/work" && "$@" >"$out/$name.out" 2>"$out/$name.err"; echo "status $?" >>"$out/$name.out")
  sed -i -E -e "s#$out/work#OUT#g" -e "s#$root#ROOT#g" -e 's/[0-9.]+ ?(s|ms|µs) (elapsed|wall)/T \2/g' \
    -e 's/(elapsed|seconds|wall_s|cpu_s|time_s)"?: ?[0-9.e+-]+/\1: T/g' -e 's/[0-9.]+ s$/T s/' -e '/: pass [0-9]+, /d' "$out/$name.out" "$out/$name.err"
}
rm -rf "$out/work"
mkdir -p "$out/work"
W="--dist weibull --shape 2 --sigma 1e-6 --radius 1e-4 --density 1e10 --area 1e-4 --modulus 1e11"
run contact-sep $asp contact $W --separation 1e-6 --law-range 0.5:3
run contact-pressure $asp contact $W --pressure 1e6
run contact-sweep $asp contact $W --sweep separation:0:4e-6:5
run contact-bounded $asp contact --dist weibull --shape 1.5 --side bounded --sigma 1e-6 --radius 1e-4 --density 1e10 --area 1e-4 --modulus 1e11 --sweep separation:-1e-6:2e-6:4
run contact-gauss $asp contact --dist gaussian --sigma 1e-6 --radius 1e-4 --density 1e10 --area 1e-4 --modulus 1e11 --sweep separation:0:3e-6:4
run contact-card $asp contact $W --export calculix --pressure-range 1e4:1e7
for law in "hertz" "chang-etsion-bogy --hardness 2e9 --law-poisson 0.3" "zhao-maietta-chang --hardness 2e9" \
  "kogut-etsion --yield-strength 1e9 --law-poisson 0.3" "jackson-green --yield-strength 1e9 --law-poisson 0.3" \
  "jackson-green --yield-strength 1e9 --law-poisson 0.3 --geometric-hardness exponential" "dmt --work-of-adhesion 0.05" \
  "jkr --work-of-adhesion 0.05" "maugis-dugdale --work-of-adhesion 0.05 --maugis-parameter 3"; do
  # shellcheck disable=SC2086
  run "law-${law%% *}-$n" $asp contact --law $law --dist gaussian --sigma 1e-6 --radius 1e-4 --density 1e10 \
    --area 1e-4 --modulus 1e11 --law-range 0.5:3 --sweep separation:1e-6:3e-6:3
done
run law-bad-key $asp contact --law hertz --hardness 1e9 --dist gaussian --sigma 1e-6 --radius 1e-4 --density 1e10 --area 1e-4 --modulus 1e11 --separation 1e-6 --law-range 0.5:3
run law-missing $asp contact --law kogut-etsion --dist gaussian --sigma 1e-6 --radius 1e-4 --density 1e10 --area 1e-4 --modulus 1e11 --separation 1e-6 --law-range 0.5:3
run law-unknown $asp contact --law nope --dist gaussian --sigma 1e-6 --radius 1e-4 --density 1e10 --area 1e-4 --modulus 1e11 --separation 1e-6 --law-range 0.5:3
for scene in "$root"/tables/scenes/*.toml; do
  b=$(basename "$scene" .toml)
  run "scene-$b" $tg --scene "$scene" --out "$b.h5"
  run "summary-$b" $asp summary --table "$b.h5"
done
run summary $asp summary
run eval-help $asp eval --help
run contact-help $asp contact --help
run surface-help $asp surface --help
run exact-help $asp exact-contact --help
run tablegen-help $tg --help
for map in "$maps"/*.x3p "$maps"/*.txt; do
  b=$(basename "$map")
  run "surface-$b" $asp surface "$map" --modulus 1e11 --pressure 1e6,1e7 --report "report-$b"
  run "surface-law-$b" $asp surface "$map" --modulus 1e11 --pressure 1e6 --law kogut-etsion --yield-strength 1e9 --law-poisson 0.3
  run "exact-$b" $asp exact-contact "$map" --modulus 1e11 --pressure 1e6,1e7
  run "exact-json-$b" $asp exact-contact "$map" --modulus 1e11 --sweep pressure:1e5:1e8:4 --json
done
# what the commands wrote: the tables' and the reports' text files (binary tables by their summary above)
find "$out/work" -type f \( -name '*.csv' -o -name '*.json' -o -name '*.txt' -o -name '*.md' -o -name '*.svg' -o -name '*.inp' \) |
  while read -r f; do rel=${f#"$out/work/"}; mkdir -p "$out/files/$(dirname "$rel")"; cp "$f" "$out/files/$rel"; done
sed -i -E 's/(elapsed|seconds|wall_s|cpu_s|time_s)"?: ?[0-9.e+-]+/\1: T/g' $(find "$out/files" -type f -name '*.json') 2>/dev/null
rm -rf "$out/work"
echo "$n runs in $out"
