# Compile time of the whole tree, set up in one place so that no CMakeLists
# names it (docs/performance.md, "Build time", has the measurements).
#
# Precompiled headers: most of a translation unit's parse time is the standard
# library, Eigen, fmt and GoogleTest, the same text in every file. Two hosts
# compile them once, one for the framework and apps and one (adding
# GoogleTest) for the targets under tests/; every other target reuses its
# host's header. Unity builds: the test targets compile their files in
# batches, so GoogleTest's and the framework headers' code is generated once a
# batch. The framework and apps are not batched: inlining across files could
# change the floating-point results.

set(CORRMP_PCH_COMMON
  <algorithm> <cmath> <cstdint> <filesystem> <functional> <map> <memory> <optional>
  <set> <stdexcept> <string> <utility> <vector>
  <fmt/format.h> <Eigen/Core> <Eigen/Geometry>)
set(CORRMP_PCH_TESTS ${CORRMP_PCH_COMMON} <gtest/gtest.h> <gmock/gmock.h>)

# Every target defined in `dir` and below it.
function(corrmp_targets_below dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    corrmp_targets_below("${sub}" below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# A header compiled with other macro definitions than a user's is not used
# (GCC) or refused (clang), so a host links what its users link for these headers.
function(corrmp_pch_host name libraries)
  set(source "${CMAKE_BINARY_DIR}/${name}.cpp")
  file(WRITE "${source}" "// Compiles the precompiled header that other targets reuse.\n")
  add_library(${name} OBJECT "${source}")
  target_link_libraries(${name} PRIVATE ${libraries})
  target_precompile_headers(${name} PRIVATE ${ARGN})
endfunction()

function(corrmp_speed_up_compiles)
  if(CORRMP_PCH)
    corrmp_pch_host(corrmp_pch_framework "Eigen3::Eigen;fmt::fmt" ${CORRMP_PCH_COMMON})
    corrmp_pch_host(corrmp_pch_tests "Eigen3::Eigen;fmt::fmt;GTest::gmock;GTest::gtest"
                    ${CORRMP_PCH_TESTS})
  endif()
  corrmp_targets_below("${PROJECT_SOURCE_DIR}" targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$"
       OR target MATCHES "^corrmp_pch_")
      continue()
    endif()
    get_target_property(dir ${target} SOURCE_DIR)
    set(host corrmp_pch_framework)
    string(FIND "${dir}/" "${PROJECT_SOURCE_DIR}/tests/" at)
    if(at EQUAL 0)
      set(host corrmp_pch_tests)
      if(CORRMP_UNITY_TESTS)
        set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 6)
      endif()
    endif()
    if(CORRMP_PCH)
      # The header's includes must resolve should the compiler not use its compiled form.
      target_link_libraries(${target} PRIVATE Eigen3::Eigen fmt::fmt)
      target_precompile_headers(${target} REUSE_FROM ${host})
    endif()
  endforeach()
endfunction()
