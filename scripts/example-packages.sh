# The example packages' build, sourced by scripts/run-examples.sh (which ships them) and
# scripts/update-goldens.sh (whose tests/golden/shaders pins their shaders), so the goldens cover
# exactly the variants the examples ship. Paths are relative to the source root.
# Every tier (matc's default), with and without the sun, with 0 or 2 point/spot lights
# (examples/scenes/lamps.json has two): 16 variants per material.
example_materials=(examples/materials/*.mat)
example_compile_options=(--point-lights 0,2)
