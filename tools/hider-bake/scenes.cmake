# The scenes baked into firmware/common/scenes/<name>.hpp: one line per scene,
# "<name>|<model relative to the source tree>|<hider-bake camera options>". Read by bake_scenes.cmake,
# which re-bakes each one (ctest hider-bake.scenes_up_to_date; target bake_scenes writes them back).
set(HIDER_BAKED_SCENES
  "torus_160x128|tests/data/models/torus.obj|--size 160x128 --eye 0,0,-2.5 --target 0,0,0 --up 0,1,0 --fov 73.7398 --near 0.25"
  "torus_320x240|tests/data/models/torus.obj|--size 320x240 --eye 0,0,-2.5 --target 0,0,0 --up 0,1,0 --fov 73.7398 --near 0.25"
  "city_street_160x128|tests/data/scenes/city-1-16-16-street.obj|--size 160x128 --eye 12.25,0.3,25.1 --target 12.25,0.5,0 --up 0,1,0 --fov 60 --near 0.5 --far 200"
  "teapot_320x240|tests/data/models/teapot.obj|--size 320x240")

# The BSP trees baked by hider-bsp into firmware/common/scenes/<name>.hpp (namespace hider::bsp_data::<name>),
# same line format; the camera options add kWidth, kHeight and kCamera (hider-render's view of the model).
set(HIDER_BAKED_BSP_SCENES
  "bsp_torus_160x128|tests/data/models/torus.obj|--size 160x128 --eye 0,0,-2.5 --target 0,0,0 --up 0,1,0 --fov 73.7398 --near 0.25"
  "bsp_city_street_160x128|tests/data/scenes/city-1-16-16-street.obj|--size 160x128 --eye 12.25,0.3,25.1 --target 12.25,0.5,0 --up 0,1,0 --fov 60 --near 0.5 --far 200")
