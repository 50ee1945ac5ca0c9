# Renderer tests (render/): headless through OSMesa, DISPLAY unset inside the tests.
# test_render links the OSMesa backend only; test_render_window (same source,
# BDFCAR_TEST_WINDOW) links the SDL2 backend only and runs it on SDL's
# "offscreen" video driver: the two GL stacks never share one executable.
bdfcar_test(test_render test_render.cpp)
target_link_libraries(test_render PRIVATE bdfcar_render_headless bdfcar_render_synthetic)
bdfcar_check_osmesa_first(test_render)

bdfcar_test(test_render_window test_render.cpp)
target_link_libraries(test_render_window PRIVATE bdfcar_render_window bdfcar_render_synthetic)
target_compile_definitions(test_render_window PRIVATE BDFCAR_TEST_WINDOW=1)

# Frame time of the headless renderer, render vs PNG encode (a tool, not a test).
add_executable(bench_render bench/bench_render.cpp)
target_link_libraries(bench_render PRIVATE bdfcar_render_headless bdfcar_render_synthetic bdfcar_warnings)
bdfcar_check_osmesa_first(bench_render)
