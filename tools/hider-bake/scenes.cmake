# The scenes baked into firmware/common/scenes/<name>.hpp: one line per scene,
# "<name>|<model relative to the source tree>|<hider-bake camera options>". Read by bake_scenes.cmake,
# which re-bakes each one (ctest hider-bake.scenes_up_to_date; target bake_scenes writes them back).
set(HIDER_BAKED_SCENES
  "torus_160x128|tests/data/models/torus.obj|--size 160x128 --eye 0,0,-2.5 --target 0,0,0 --up 0,1,0 --fov 73.7398 --near 0.25"
  "torus_320x240|tests/data/models/torus.obj|--size 320x240 --eye 0,0,-2.5 --target 0,0,0 --up 0,1,0 --fov 73.7398 --near 0.25"
  "teapot_320x240|tests/data/models/teapot.obj|--size 320x240")
