# Microbenchmarks (Google Benchmark, Debian's libbenchmark-dev) of the core's hot kernels:
# footprint/sweep overlap checks, state-graph building, dependency search and decomposition,
# and the plan validator. Not part of `all`: build with the `microbenchmarks` target and run
# with scripts/microbench (which passes its arguments to the binary, e.g. --benchmark_filter).
find_package(benchmark QUIET)
if(NOT benchmark_FOUND)
  message(STATUS "Google Benchmark not found (apt-get install libbenchmark-dev): no microbenchmarks target")
  return()
endif()

file(GLOB MICROBENCH_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/bench/*.cpp)
add_executable(fleet_planner_microbench EXCLUDE_FROM_ALL ${MICROBENCH_SOURCES})
target_link_libraries(fleet_planner_microbench fleet_planner_core benchmark::benchmark_main)
# The shared benchmark maps and pools, unless $FLEET_PLANNER_BENCHMARK names another folder.
get_filename_component(FLEET_PLANNER_BENCHMARK_DIR ${CMAKE_CURRENT_SOURCE_DIR}/../shared/benchmark ABSOLUTE)
target_compile_definitions(fleet_planner_microbench PRIVATE
  FLEET_PLANNER_BENCHMARK_DIR="${FLEET_PLANNER_BENCHMARK_DIR}")
set_target_properties(fleet_planner_microbench PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/lib/fleet_planner)
add_custom_target(microbenchmarks DEPENDS fleet_planner_microbench)
