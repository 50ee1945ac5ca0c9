# input/: mapping files, axis response, keyboard ramps, hot-plug and fallback,
# all on SDL virtual devices (no hardware, no display: SDL_VIDEODRIVER=dummy);
# test_input_setup: calibration, pedal rests, the force-feedback test and
# speed-sensitive steering.
add_library(bdfcar_test_input_virtual STATIC input_virtual.cpp)
target_link_libraries(bdfcar_test_input_virtual PUBLIC SDL2::SDL2 GTest::gtest PRIVATE bdfcar_warnings)
bdfcar_test(test_input test_input.cpp)
target_link_libraries(test_input PRIVATE bdfcar_input bdfcar_test_input_virtual SDL2::SDL2)
target_compile_definitions(test_input PRIVATE BDFCAR_SHIPPED_INPUT_DIR="${PROJECT_SOURCE_DIR}/assets/input")
bdfcar_test(test_input_setup test_input_setup.cpp)
target_link_libraries(test_input_setup PRIVATE bdfcar_input bdfcar_config bdfcar_test_input_virtual SDL2::SDL2)
target_compile_definitions(test_input_setup PRIVATE BDFCAR_SHIPPED_INPUT_DIR="${PROJECT_SOURCE_DIR}/assets/input")
# A new driver's keys through a corner at 60 km/h with the shipped keyboard
# mapping (issue 30), and without its speed-sensitive steering for contrast.
bdfcar_test(test_keyboard_driving test_keyboard_driving.cpp)
target_link_libraries(test_keyboard_driving PRIVATE bdfcar_input bdfcar_app_core bdfcar_test_input_virtual SDL2::SDL2)
target_compile_definitions(test_keyboard_driving PRIVATE BDFCAR_SHIPPED_INPUT_DIR="${PROJECT_SOURCE_DIR}/assets/input"
                                                    BDFCAR_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
