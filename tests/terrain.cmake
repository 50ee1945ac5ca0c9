# Terrain tests (registered with ctest) and the ray benchmark (run by hand:
# build-dir/tests/bench_terrain --benchmark_repetitions=5 --benchmark_report_aggregates_only=true).
find_package(Threads REQUIRED)

bdfcar_test(test_terrain test_terrain.cpp)
target_link_libraries(test_terrain PRIVATE bdfcar_terrain_bullet bdfcar_terrain Threads::Threads)
target_compile_definitions(test_terrain PRIVATE BDFCAR_ASSETS_DIR="${PROJECT_SOURCE_DIR}/assets")
# The no-allocation-per-ray test replaces malloc and friends, which
# AddressSanitizer must own: with the counters off (sanitizer builds) the
# replacement is compiled out and that one test reports itself skipped.
if(BDFCAR_ALLOCATION_COUNTERS)
  target_compile_definitions(test_terrain PRIVATE BDFCAR_ALLOCATION_COUNTERS=1)
endif()

add_executable(bench_terrain bench/bench_terrain.cpp)
target_link_libraries(bench_terrain PRIVATE bdfcar_terrain_bullet bdfcar_terrain benchmark::benchmark bdfcar_warnings)
target_compile_definitions(bench_terrain PRIVATE BDFCAR_ASSETS_DIR="${PROJECT_SOURCE_DIR}/assets")

bdfcar_test(test_proving_ground test_proving_ground.cpp)
target_link_libraries(test_proving_ground PRIVATE bdfcar_terrain_bullet bdfcar_terrain)
target_compile_definitions(test_proving_ground PRIVATE BDFCAR_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
