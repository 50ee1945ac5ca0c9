# input/: mapping files, axis response, keyboard ramps, hot-plug and fallback,
# all on SDL virtual devices (no hardware, no display: SDL_VIDEODRIVER=dummy).
bdfcar_test(test_input test_input.cpp)
target_link_libraries(test_input PRIVATE bdfcar_input SDL2::SDL2)
target_compile_definitions(test_input PRIVATE BDFCAR_SHIPPED_INPUT_DIR="${PROJECT_SOURCE_DIR}/assets/input")
