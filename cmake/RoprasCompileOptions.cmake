# Warnings and SIMD flags for the project's own targets only (no global flag mutation).
add_library(ropras_warnings INTERFACE)
target_compile_options(ropras_warnings INTERFACE -Wall -Wextra -Wpedantic)

# SIMD: native build (AVX2+FMA on the machines we use) or a portable one. The kernels pick the AVX2
# backend when the compiler targets AVX2 and always compile the scalar backend too (tests use both).
add_library(ropras_simd_flags INTERFACE)
if(ROPRAS_NATIVE_SIMD)
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=native ROPRAS_HAS_MARCH_NATIVE)
  if(ROPRAS_HAS_MARCH_NATIVE)
    target_compile_options(ropras_simd_flags INTERFACE -march=native)
  endif()
endif()

# Helper: a project library with the usual options.
function(ropras_add_library name)
  # INCLUDE_DIRS: subfolders that each hold an include/ (scenarios/<family>/include); default: this folder's include/.
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS;INCLUDE_DIRS" ${ARGN})
  add_library(ropras_${name} ${ARG_SOURCES})
  add_library(ropras::${name} ALIAS ropras_${name})
  set_target_properties(ropras_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME ropras_${name})
  if(NOT ARG_INCLUDE_DIRS)
    set(ARG_INCLUDE_DIRS ".")
  endif()
  foreach(dir IN LISTS ARG_INCLUDE_DIRS)
    target_include_directories(ropras_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/${dir}/include>)
    install(DIRECTORY ${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endforeach()
  target_include_directories(ropras_${name} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(ropras_${name} PUBLIC ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS}
                                                                          $<BUILD_INTERFACE:ropras_warnings>)
  install(TARGETS ropras_${name} EXPORT roprasTargets)
endfunction()
