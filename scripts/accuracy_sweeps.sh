#!/bin/sh
# Dense sweeps (10,000 points each) of the physics nodes on both GL targets with
# `watergraph probe --node TYPE --sweep`, a summary line per sweep (points over the error
# bound, max error, worst error/bound), and the error plots of docs/accuracy.md drawn with
# gnuplot (gnuplot-nox, installed by scripts/setup.sh). Not part of CI (the gtest
# FresnelBound runs the Fresnel sweep there). Usage, from the repository root:
#   scripts/accuracy_sweeps.sh [path/to/watergraph]      (default build/bin/watergraph)
set -eu
wg=${1:-build/bin/watergraph}
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
status=0

# sweep NAME NODE AXIS OPTIONS TARGET [CASES]: one sweep (of the first case of the CASES
# file, else the node's default case), its table kept as $data/NAME-TARGET.dat
sweep() {
  if ! "$wg" probe --node "$2" --sweep "$3" --options "$4" --target "$5" --table "$data/$1-$5.dat" \
      ${6:+--cases "$6"} 2>"$data/log"; then
    status=1
  fi
  printf '%-8s %-36s %s\n' "$5" "$1" "$(tail -n 1 "$data/log")"
}

# A low sun behind the water seen at half a degree (its glitter path): the light's
# elevation swept from 0.06 to 20 degrees, where L + V nearly cancels.
glitter='"normal": [0, 1, 0], "view": [0.99996192306417131, 0.0087265354983739347, 0], "light": [-1, 0.01, 0]'
printf '{"cases": [{"name": "glitter", "inputs": {%s}}]}' "$glitter" >"$data/glitter.json"
printf '{"cases": [{"name": "glitter", "inputs": {%s, "shininess": 2048}}]}' "$glitter" >"$data/glitter-sharp.json"

for target in glsl330 es300; do
  for dir in air_to_water water_to_air; do
    for model in exact schlick; do
      sweep "fresnel-$model-$dir" fresnel angle:0:90:10000 "{\"model\":\"$model\",\"direction\":\"$dir\"}" $target
    done
    sweep "fresnel-power-$dir" fresnel angle:0:90:10000 "{\"model\":\"power\",\"direction\":\"$dir\"}" $target
    sweep "refract_dir-$dir" refract_dir angle:0:90:10000 "{\"direction\":\"$dir\"}" $target
  done
  sweep absorption-distance absorption distance:0:300:10000 '{}' $target
  sweep gerstner-position-x gerstner_waves position.x:0:100000:10000 '{}' $target
  sweep gerstner-time gerstner_waves time:0:1000000:10000 '{}' $target
  sweep trochoid-origin-x trochoid_wave origin.x:0:1000:10000 '{}' $target
  sweep subsurface-angle subsurface angle:0:180:10000 '{}' $target
  sweep ggx-roughness ggx_specular roughness:0.001:1:10000 '{}' $target
  sweep ggx-glitter ggx_specular light.y:0.001:0.36:10000 '{}' $target "$data/glitter.json"
  sweep blinn_phong-glitter blinn_phong light.y:0.001:0.36:10000 '{}' $target "$data/glitter-sharp.json"
  sweep value_noise-x value_noise p.x:0:100000:10000 '{}' $target
  sweep fbm-x fbm p.x:0:1000:10000 '{}' $target
  sweep voronoi-x voronoi p.x:0:1000:10000 '{}' $target
  sweep voronoi_caustics-x voronoi_caustics p.x:0:250:10000 '{}' $target
done

command -v gnuplot >/dev/null 2>&1 || { echo "gnuplot not found; install gnuplot-nox (scripts/setup.sh)" >&2; exit 2; }
critical=48.6066
gnuplot <<GP
set terminal pngcairo size 1100,650 font 'sans,10'
set output 'docs/images/fresnel-error.png'
set title 'fresnel: float32 error against the double reference (llvmpipe, glsl330; es300 is identical), 10,000 angles'
set xlabel 'angle between normal and view (degrees)'
set ylabel '|gpu - ref|  (zero errors drawn at 1e-10)'
set logscale y
set format y '10^{%L}'
set yrange [1e-10:1e-1]
set grid
set key left top
set arrow from $critical, graph 0 to $critical, graph 1 nohead dt 2 lc rgb 'black'
set label 'critical angle 48.6066' at $critical + 1, graph 0.95
plot '$data/fresnel-exact-water_to_air-glsl330.dat' using 1:(\$4 > 0 ? \$4 : 1e-10) with points pt 7 ps 0.25 lc 1 title 'exact, water to air: error', \
     '' using 1:5 with lines lw 1.5 lc 1 title 'exact, water to air: bound', \
     '$data/fresnel-schlick-water_to_air-glsl330.dat' using 1:(\$4 > 0 ? \$4 : 1e-10) with points pt 7 ps 0.25 lc 2 title 'schlick, water to air: error', \
     '$data/fresnel-exact-air_to_water-glsl330.dat' using 1:(\$4 > 0 ? \$4 : 1e-10) with points pt 7 ps 0.25 lc 3 title 'exact, air to water: error', \
     '' using 1:5 with lines lw 1.5 lc 3 title 'exact, air to water: bound'
GP
paste "$data/fresnel-exact-air_to_water-glsl330.dat" "$data/fresnel-schlick-air_to_water-glsl330.dat" \
  "$data/fresnel-power-air_to_water-glsl330.dat" "$data/fresnel-exact-water_to_air-glsl330.dat" \
  "$data/fresnel-schlick-water_to_air-glsl330.dat" | grep -v '^#' >"$data/models.dat"
gnuplot <<GP
set terminal pngcairo size 1100,650 font 'sans,10'
set output 'docs/images/fresnel-models.png'
set title "fresnel: Schlick's and the power model's reflectance minus the exact one (double reference)"
set xlabel 'angle between normal and view (degrees)'
set ylabel 'F(model) - F(exact)'
set grid
set key left bottom
set arrow from $critical, graph 0 to $critical, graph 1 nohead dt 2 lc rgb 'black'
set label 'critical angle 48.6066 (from below)' at $critical + 1, graph 0.95
plot '$data/models.dat' using 1:(\$8 - \$3) with lines lw 2 lc 2 title 'schlick - exact, air to water', \
     '' using 1:(\$13 - \$3) with lines lw 2 lc 4 title 'power (1 - cos^2) - exact, air to water', \
     '' using 1:(\$23 - \$18) with lines lw 2 dt 2 lc 2 title 'schlick - exact, water to air'
GP
echo "plots: docs/images/fresnel-error.png docs/images/fresnel-models.png"
exit $status
