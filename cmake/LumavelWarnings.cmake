# Warning sets. The firmware tree builds with warnings as errors on every target.
set(LUMAVEL_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
    -Wcast-align -Wnull-dereference -Wdouble-promotion)
set(LUMAVEL_FIRMWARE_WARNINGS ${LUMAVEL_WARNINGS} -Werror -Wfloat-equal)
# Firmware rules that the compiler can enforce: no exceptions, no RTTI.
set(LUMAVEL_FIRMWARE_FLAGS -fno-exceptions -fno-rtti)

# Adds each existing subdirectory of the current folder, in order, so that
# areas can grow independently without editing their parent.
function(lumavel_add_existing_subdirs)
  foreach(d ${ARGN})
    if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${d}/CMakeLists.txt)
      add_subdirectory(${d})
    endif()
  endforeach()
endfunction()
