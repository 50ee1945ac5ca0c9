# Renderer tests (render/): headless through OSMesa, DISPLAY unset inside the tests.
# test_render links the OSMesa backend only; test_render_window (same source,
# BDFCAR_TEST_WINDOW) links the SDL2 backend only and runs it on SDL's
# "offscreen" video driver: the two GL stacks never share one executable.
bdfcar_test(test_render test_render.cpp)
target_link_libraries(test_render PRIVATE bdfcar_render_headless bdfcar_render_synthetic)
bdfcar_check_osmesa_first(test_render)

# Under the sanitizers (scripts/sanitize.sh) the SDL/glvnd GL driver is
# unloaded before LeakSanitizer looks, so its allocations show as leaks with no
# module name to suppress: no leak check for this executable there (ASan and
# UBSan still run).
if(BDFCAR_SANITIZE)
  add_executable(test_render_window test_render.cpp)
  target_link_libraries(test_render_window PRIVATE GTest::gtest GTest::gtest_main bdfcar_warnings)
  gtest_discover_tests(test_render_window DISCOVERY_TIMEOUT 60
                       PROPERTIES TIMEOUT 300 ENVIRONMENT "LSAN_OPTIONS=detect_leaks=0")
else()
  bdfcar_test(test_render_window test_render.cpp)
endif()
target_link_libraries(test_render_window PRIVATE bdfcar_render_window bdfcar_render_synthetic)
target_compile_definitions(test_render_window PRIVATE BDFCAR_TEST_WINDOW=1)

# Frame time of the headless renderer, render vs PNG encode (a tool, not a test).
add_executable(bench_render bench/bench_render.cpp)
target_link_libraries(bench_render PRIVATE bdfcar_render_headless bdfcar_render_synthetic bdfcar_warnings)
bdfcar_check_osmesa_first(bench_render)

# The ground's levels of detail: geometry only, no GL context.
bdfcar_test(test_terrain_lod test_terrain_lod.cpp)
target_link_libraries(test_terrain_lod PRIVATE bdfcar_render_scene)
target_compile_definitions(test_terrain_lod PRIVATE BDFCAR_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

# Background priorities of encoders and drawing threads (no GL).
bdfcar_test(test_thread_priority test_thread_priority.cpp)
target_link_libraries(test_thread_priority PRIVATE bdfcar_render_output)

# The drive window's choice of the world's resolution from frame times (no GL).
bdfcar_test(test_resolution_governor test_resolution_governor.cpp)
target_link_libraries(test_resolution_governor PRIVATE bdfcar_render_output)
