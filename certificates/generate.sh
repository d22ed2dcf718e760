#!/usr/bin/env bash
# Regenerates certificates/valid/ with `chatter certify` (output is deterministic).
# Each line below is a body; every claim that certifies for it is written.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/chatter
out=certificates/valid
written=0
while read -r n kappa gamma note; do
  for claim in effectively-invariant cc-or-pcc-from-all-down complete-chatter-from-all-down; do
    f="$out/n${n}-kappa${kappa//\//_}-gamma${gamma//\//_}-${claim}.ron"
    if "$bin" certify --n "$n" --kappa "$kappa" --gamma "$gamma" --claim "$claim" -o "$f" >/dev/null; then
      written=$((written + 1))
    else
      rm -f "$f"
      echo "not certified: n=$n kappa=$kappa gamma=$gamma $claim ($note)"
    fi
  done
done <<'BODIES'
4 1/6 1/100 flat-square-plate
4 1/6 1/50 flat-square-plate
4 1/6 1/1000 flat-square-plate-pcc-possible
4 1/8 1/40 square-low-inertia
4 1/10 1/20 square
4 1/20 1/10 square
3 1/8 1/100 flat-triangle-plate-pcc-possible
3 1/8 3/100 flat-triangle-plate
3 3/20 1/20 tetrahedron
3 3/20 1/10 tetrahedron
3 1/10 3/20 triangle
3 1/40 1/5 triangle
6 1/20 1/1000 hexagon
6 1/40 1/100 hexagon
6 1/40 1/20 hexagon
4 1/6 0 square-plastic
3 3/20 0 tetrahedron-plastic
2 1/3 1/20 uniform-rod
2 1/3 7/100 uniform-rod-just-below-7-4sqrt3
2 1/10 1/5 light-rod
2 1/4 1/9 rod-on-goyals-boundary
BODIES
# A large certificate (64 generators) for the verification benchmark (benches/verify.rs).
"$bin" certify --n 3 --kappa 3/20 --gamma 1/20 --claim effectively-invariant --max-vertices 60 \
  -o "$out/n3-kappa3_20-gamma1_20-64-generators.ron" >/dev/null
written=$((written + 1))
# Box certificates (format version 2): one cone for every (kappa, gamma) of a box.
while read -r n kappa gamma note; do
  name="n${n}-kappa${kappa//[\/:]/_}-gamma${gamma//[\/:]/_}-box.ron"
  if "$bin" certify --n "$n" --kappa "$kappa" --gamma "$gamma" -o "$out/$name" >/dev/null; then
    written=$((written + 1))
  else
    rm -f "$out/$name"
    echo "not certified: box n=$n kappa=$kappa gamma=$gamma ($note)"
  fi
done <<'BOXES'
4 1/10:3/25 1/100:1/50 square
3 1/10:1/8 1/100:1/20 triangle-pcc-possible
3 3/20:1/6 1/20:3/40 tetrahedron
6 1/40:1/30 1/100:1/50 hexagon
2 1/4:1/3 1/100:1/20 rod
BOXES
# Refutations: exact derivations that no effectively invariant cone contains the seeds.
while read -r n kappa gamma claim name; do
  "$bin" refute --n "$n" --kappa "$kappa" --gamma "$gamma" --claim "$claim" -o "$out/$name" >/dev/null
  written=$((written + 1))
done <<'REFUTATIONS'
4 1/6 1/20 effectively-invariant refutation-n4-kappa1_6-gamma1_20.ron
3 1/8 1/5 cc-or-pcc-from-all-down refutation-n3-kappa1_8-gamma1_5-all-down.ron
6 1/20 1/10 effectively-invariant refutation-n6-kappa1_20-gamma1_10.ron
2 1/3 1/10 effectively-invariant refutation-n2-kappa1_3-gamma1_10.ron
REFUTATIONS
# A general body given by its full inertia tensor (rule K0 checks that J is its J_eff): the
# catalogue's lander, built from its 3-D geometry (docs/bodies.md).
"$bin" certify --body lander --gamma 1/20 -o "$out/convex-lander-gamma1_20-inertia-tensor.ron" >/dev/null
written=$((written + 1))
# The same lander for every gamma of [1/50, 14769/250000]: the upper end lies 5.8e-6 (relative)
# below its conjectural CC threshold 0.0590763452... (docs/bodies.md, issue 25 §4).
"$bin" certify --body lander --gamma 1/50:14769/250000 \
  -o "$out/convex-lander-gamma1_50-14769_250000-inertia-tensor.ron" >/dev/null
written=$((written + 1))
# JSON twins (docs/certificate-format.md §11) of the doc example, of a refutation and of a basin
# certificate (written by `chatter basin`, docs/basin-certificates.md; not regenerated here).
for name in doc-example-square refutation-n4-kappa1_6-gamma1_20 basin-icc-n3-kappa1_8-gamma1_2; do
  "$bin" convert "$out/$name.ron" --to json -o "$out/$name.json"
  written=$((written + 1))
done
echo "$written certificates in $out"
