#!/usr/bin/env bash
# The main job: install dependencies, build Facet, compile the example materials with matc and
# render the example scenes with both backends (Vulkan on lavapipe, GL on OSMesa) to PNG.
#   build/release/                     the build
#   build/examples/packages/*.matpkg   compiled materials (+ sources/ with every generated shader)
#   build/examples/imported/<asset>/   `matc import` of each glTF asset in examples/assets/
#   build/examples/images/*.png        rendered scenes, one per backend
#   build/examples/eval/               matc eval of red_plastic: report.md, report.json, plot.svg, images/
#   build/examples/tune/               matc tune of red_plastic: report.md, report.json, plot.svg
#   build/examples/images/app.png      examples/app: the runtime embedded on the app's own Vulkan device
#   build/examples/images/app_gl.png   examples/app_gl: the same on the app's own OpenGL ES context
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup-deps.sh

jobs=$(nproc)
cmake --preset release  # build/release, CMakePresets.json
cmake --build --preset release --parallel "$jobs" --target matc facet-gltf-import facet-eval facet-tune facet-texture facet-view facet-app-example facet-app-gl-example

packages=build/examples/packages
images=build/examples/images
mkdir -p "$packages" "$images"
# The variants scripts/example-packages.sh names (tests/golden/shaders pins their shaders).
source scripts/example-packages.sh
for material in "${example_materials[@]}"; do
  name=$(basename "$material" .mat)
  build/release/matc/matc compile "$material" -o "$packages/$name.matpkg" "${example_compile_options[@]}" \
    --emit-source "$packages/sources"
done
# The ASTC textures of tiles_astc.json, encoded as a build encodes them (docs/texture-format.md):
# the same bytes as the committed ones.
mkdir -p build/examples/textures
build/release/matc/matc texture examples/scenes/textures/tiles.png -o build/examples/textures/tiles.ktx2 --usage color
build/release/matc/matc texture examples/scenes/textures/tiles_normal.png -o build/examples/textures/tiles_normal.ktx2 \
  --usage normal
cmp build/examples/textures/tiles.ktx2 examples/scenes/textures/tiles.ktx2
cmp build/examples/textures/tiles_normal.ktx2 examples/scenes/textures/tiles_normal.ktx2
for scene in examples/scenes/*.json; do
  if grep -q '"castShadows": true' "$scene"; then
    # A sun that casts (yard.json): its packages built with --scene (the receivers and depth-only
    # programs it asks for).
    name=$(basename "$scene" .json)
    mkdir -p "$packages/$name"
    for material in $(grep -o '"material": "[a-z_]*"' "$scene" | cut -d'"' -f4 | sort -u); do
      build/release/matc/matc compile "examples/materials/$material.mat" -o "$packages/$name/$material.matpkg" \
        --scene "$scene"
    done
    build/release/runtime/viewer/facet-view "$scene" --packages "$packages/$name" --out "$images" --validation
    continue
  fi
  build/release/runtime/viewer/facet-view "$scene" --packages "$packages" --out "$images" --validation
done
# The committed glTF assets with their own materials (docs/gltf.md): `matc import` writes a .mat
# per feature set, compiled beside the example materials; examples/scenes/gltf/<asset>.json draws
# the asset with them, reading its files from examples/assets/ (hence --asset-root examples).
for gltf in examples/assets/*/*.gltf; do
  imported=build/examples/imported/$(basename "$(dirname "$gltf")")
  rm -rf "$imported"
  build/release/matc/matc import "$gltf" -o "$imported" --asset-root examples
  for material in "$imported"/*.mat; do
    build/release/matc/matc compile "$material" -o "$packages/$(basename "$material" .mat).matpkg" \
      --emit-source "$packages/sources"
  done
done
for scene in examples/scenes/gltf/*.json; do
  build/release/runtime/viewer/facet-view "$scene" --packages "$packages" --out "$images" --asset-root examples \
    --validation
done
# The three-material scene once per tier, to compare what each tier's maths looks like.
for tier in reference high mid low; do
  build/release/runtime/viewer/facet-view examples/scenes/spheres.json --tier "$tier" \
    --packages "$packages" --out "$images" --validation
done

# examples/app: an engine's use of the runtime (its own Vulkan device, two material instances),
# with validation on: any validation error fails it.
FACET_VK_VALIDATION=1 build/release/examples/app/facet-app-example \
  build/release/examples/app/red_plastic.matpkg "$images/app.png"
# examples/app_gl: the same on the app's own OpenGL ES context (EGL), the runtime linking no OSMesa.
build/release/examples/app_gl/facet-app-gl-example build/release/examples/app/red_plastic.matpkg "$images/app_gl.png"

# Speed against error (docs/eval.md): every tier and single-option swap of one material, rendered
# on lavapipe and measured against `reference` and by the mobile cost model.
rm -rf build/examples/eval
build/release/matc/matc eval examples/materials/red_plastic.mat --out build/examples/eval
# Each tier's cheapest configuration within its error budget (docs/tune.md), then the gate on the
# committed choices (examples/materials/red_plastic.tuning.json). Three axes of change, as the
# committed file was written: its high (ggx_fastv, the irradiance cube, no compensation) is three
# axes from every preset.
rm -rf build/examples/tune
build/release/matc/matc tune examples/materials/red_plastic.mat --budgets examples/lint/tune_budgets.json \
  --max-changes 3 --out build/examples/tune
build/release/matc/matc tune examples/materials/red_plastic.mat --budgets examples/lint/tune_budgets.json --check

echo
echo "Packages: $(pwd)/$packages"
echo "Images:   $(pwd)/$images"
ls -1 "$images"/*.png
echo "Eval:     $(pwd)/build/examples/eval/report.md (plot.svg, report.json, images/)"
echo "Tune:     $(pwd)/build/examples/tune/report.md (report.json, plot.svg)"
