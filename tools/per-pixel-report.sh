#!/usr/bin/env bash
# Renders what the per-pixel sections of docs/ACCURACY.md measure, then writes them with
# tools/per_pixel_report.py (issues 13 and 20):
#   - the default render against the exact-intersection reference (--exact-geometry), for
#     every classic and figure scene that reference can render: bias, noise, the share of
#     squared error in the worst 1 % of pixels, the crossover sample count, signed error
#     images, and the hit tolerance, step limit and over-relaxation judged against it;
#   - the Sobol sampler against independent samples, for every classic and figure scene:
#     noise at equal sample count and at equal time, convergence, time per sample;
#   - 1- and 4-spp images of a flat lit plane, to look for the sampler's structured artefacts;
#   - marched solids where they meet other surfaces (issue 36, bench/scenes/creases/): the
#     default render against exact intersection where the solid is a sharp CSG block of
#     closed-form shapes, against the converged march where none exists, the converged march
#     against exact intersection and against itself at half its tolerance, and, with
#     PER_PIXEL_BASELINE set to another build's raytracer, that build's default render too.
#
#   tools/per-pixel-report.sh            renders what is missing from the cache, then writes
#   PER_PIXEL_REFRESH=1 tools/per-pixel-report.sh   renders everything again
#   PER_PIXEL_ONLY=creases tools/per-pixel-report.sh   the marched solids' section alone
#
# Renders go to build-accuracy/per-pixel/ (git ignores it); each is an EXR with its sample
# counts and second moments, so each step of a sample-count ladder resumes the previous one.
# On 2 cores with llvmpipe and nothing else running, a full run takes about 40 minutes.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$root/build/raytracer"
cache="${PER_PIXEL_CACHE:-$root/build-accuracy/per-pixel}"
size=(160 120)
ladder=(4 16 64 256 1024)
exact_spp=1024
settings_spp=256
# The marched solids' section: default renders up to this, references at this.
crease_spp="${PER_PIXEL_CREASE_SPP:-1024}"
mkdir -p "$cache"

"$root/tools/install-dependencies.sh" python3-matplotlib
[ -x "$program" ] || "$root/tools/build.sh"

classic=(scene1 scene2 scene3 scene4 scene5 scene6 scene7)
# The -usersdf figure scenes are their CSG twins written as user SDFs (the same picture).
figures=(fig02-materials-cornell fig03-shadows-point-light fig03-shadows-sphere-light
         fig04-csg-solid fig06-triplanar-textures fig07-glass-textures-lights
         fig09-glass-mirrors-checker fig10-many-objects-glossy-floor fig11-torus-knot
         fig12-csg-diffuse fig13-glass-mirror-cornell fig14-smooth-csg-cornell-usersdf)
# The accuracy settings judged against the exact reference, on the scenes that march.
settings=("--hit-tolerance 0.0625" "--hit-tolerance 0.125" "--hit-tolerance 0.5"
          "--hit-tolerance 1" "--max-steps 64" "--max-steps 128"
          "--over-relaxation 1" "--over-relaxation 1.5")

timings="$cache/timings.csv"
[ -f "$timings" ] || echo "scene,variant,seed,from_spp,to_spp,seconds" >"$timings"

# The converged march, the reference for marched solids that have no exact intersection: a
# sixteenth of the default hit tolerance and eight times its steps; and the same at half that
# tolerance, which must not differ from it (docs/ACCURACY.md).
converged=(--hit-tolerance 0.015625 --max-steps 4096)
halved=(--hit-tolerance 0.0078125 --max-steps 8192)

scene_file() {
  if [ -f "$root/scenes/$1.in" ]; then echo "$root/scenes/$1.in"; else echo "$root/bench/scenes/creases/$1.in"; fi
}

# render NAME VARIANT SEED SPP [options...]: NAME-VARIANT-sSEED-SPP.exr, resuming the
# largest cached smaller count of the same ladder when there is one. RENDER_PROGRAM, when
# set, renders instead of this build's program.
render() {
  local name="$1" variant="$2" seed="$3" spp="$4"
  local program="${RENDER_PROGRAM:-$program}" scene
  scene="$(scene_file "$name")"
  shift 4
  local out="$cache/$name-$variant-s$seed-$spp.exr"
  if [ -f "$out" ] && [ -z "${PER_PIXEL_REFRESH:-}" ]; then return 0; fi
  local previous="" from=0 n
  for n in "${ladder[@]}"; do
    if [ "$n" -lt "$spp" ] && [ -f "$cache/$name-$variant-s$seed-$n.exr" ]; then
      previous="$cache/$name-$variant-s$seed-$n.exr"
      from=$n
    fi
  done
  local start end
  start=$(date +%s.%N)
  if [ -n "$previous" ]; then
    "$program" "$scene" --resume "$previous" --spp "$spp" --quiet \
      --headless --output "$out" "$@"
  else
    "$program" "$scene" "${size[@]}" --spp "$spp" --seed "$seed" --quiet \
      --headless --output "$out" "$@"
  fi
  end=$(date +%s.%N)
  echo "$name,$variant,$seed,$from,$spp,$(echo "$end - $start" | bc)" >>"$timings"
}

exact_capable() {
  "$program" "$root/scenes/$1.in" 8 6 --spp 1 --exact-geometry --quiet --headless \
    --output "$cache/probe.exr" >/dev/null 2>&1
}

all_scenes=("${classic[@]}" "${figures[@]}")
[ "${PER_PIXEL_ONLY:-}" = creases ] && all_scenes=()
for name in "${all_scenes[@]}"; do
  echo "== $name"
  # Both samplers up to 256 spp; Sobol, the default, on to 1024 where the exact reference
  # can judge its bias.
  for sampler in sobol independent; do
    for seed in 1 2; do
      for n in "${ladder[@]}"; do
        [ "$n" -le 256 ] || continue
        render "$name" "$sampler" "$seed" "$n" --sampler "$sampler"
      done
    done
  done
  if exact_capable "$name"; then
    for seed in 1 2; do render "$name" sobol "$seed" 1024 --sampler sobol; done
    for seed in 11 12; do render "$name" exact "$seed" "$exact_spp" --exact-geometry; done
    # (The shader in a variable, not a pipe: grep -q leaving early would fail the pipe.)
    shader="$("$program" "$root/scenes/$name.in" --print-shader 2>/dev/null)"
    if grep -q "define HAS_MARCHED_OBJECTS 1" <<<"$shader"; then
      for setting in "${settings[@]}"; do
        variant="$(echo "$setting" | tr -d '-' | tr ' ' '=')"
        for seed in 1 2; do
          # shellcheck disable=SC2086 # the setting is an option and its value
          render "$name" "$variant" "$seed" "$settings_spp" $setting
        done
      done
    fi
  fi
done

# Marched solids where they meet other surfaces: each against exact intersection where it
# has one, else against the converged march; the converged march judged in turn.
for entry in difference-on-floor:exact intersection-on-floor:exact \
             smooth-union-in-room:converged user-sdf-against-wall:converged; do
  name="${entry%%:*}" reference="${entry#*:}"
  echo "== $name"
  for seed in 1 2; do
    for n in "${ladder[@]}"; do [ "$n" -gt "$crease_spp" ] || render "$name" sobol "$seed" "$n"; done
    if [ -n "${PER_PIXEL_BASELINE:-}" ]; then
      RENDER_PROGRAM="$PER_PIXEL_BASELINE" render "$name" before "$seed" "$crease_spp"
    fi
  done
  for seed in 11 12; do
    render "$name" converged "$seed" "$crease_spp" "${converged[@]}"
    if [ "$reference" = exact ]; then
      render "$name" exact "$seed" "$crease_spp" --exact-geometry
    else
      render "$name" halved "$seed" "$crease_spp" "${halved[@]}"
    fi
  done
done

# The flat lit plane at 1 and 4 spp, each sampler, and a 1024-spp render to subtract.
flat_samplers=(sobol independent)
[ "${PER_PIXEL_ONLY:-}" = creases ] && flat_samplers=()
for sampler in "${flat_samplers[@]}"; do
  for spp in 1 4; do
    out="$cache/flat-plane-$sampler-$spp.exr"
    [ -f "$out" ] && [ -z "${PER_PIXEL_REFRESH:-}" ] && continue
    "$program" "$root/bench/scenes/flat-lit-plane.in" 320 240 --spp "$spp" --quiet \
      --headless --sampler "$sampler" --output "$out"
  done
done
reference="$cache/flat-plane-reference.exr"
if [ "${PER_PIXEL_ONLY:-}" != creases ] && { [ ! -f "$reference" ] || [ -n "${PER_PIXEL_REFRESH:-}" ]; }; then
  "$program" "$root/bench/scenes/flat-lit-plane.in" 320 240 --spp 1024 --quiet --headless \
    --sampler independent --seed 99 --output "$reference"
fi
rm -f "$cache/probe.exr"

# -s: Debian's numpy, the one its matplotlib was built for, not a pip-installed one in ~/.local
/usr/bin/python3 -s "$root/tools/per_pixel_report.py" "$cache" "$root/docs/ACCURACY.md" \
  "$root/docs/accuracy/per-pixel" --size "${size[@]}" --exact-spp "$exact_spp" \
  --settings-spp "$settings_spp" --crease-spp "$crease_spp" \
  --command "tools/per-pixel-report.sh" \
  ${PER_PIXEL_ONLY:+--only-creases}
