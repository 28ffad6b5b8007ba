# Script mode: fails if a linked firmware image contains soft-float helpers,
# libm, heap or exception machinery. The image is linked with --gc-sections,
# so every symbol left in it was really pulled in by the code.
#   cmake -DELF=fw.elf -DNM=arm-none-eabi-nm [-DMAP=fw.map] [-DALLOW=<regex>] -P LumavelCheckForbiddenSymbols.cmake
# ALLOW exempts symbols the board defines itself on purpose (boards/common/no_heap.cpp:
# trapping operator delete for the HAL's deleting destructors; operator new stays forbidden).
if(NOT ELF OR NOT NM)
  message(FATAL_ERROR "usage: -DELF=<image> -DNM=<nm> [-DMAP=<map>] -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
execute_process(COMMAND ${NM} --defined-only ${ELF} OUTPUT_VARIABLE syms RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${ELF}")
endif()

# One regex per family, so the failure names the reason.
set(families
  "soft-float (EABI)=^__aeabi_(f|d|[iu]?l?2[fd]|ul2[fd]|cf|cd)"
  "soft-float (libgcc)=^__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord|float|fix|extend|trunc|pow|abs)[a-z]*(sf|df|tf|xf|hf|sc|dc)[a-z0-9]*$"
  "libm=^(sqrtf?|sinf?|cosf?|tanf?|atan2?f?|expf?|logf?|powf?|floorf?|ceilf?|fabsf?|lrintf?|roundf?)$"
  "heap=^_?(malloc|free|calloc|realloc|_malloc_r|_free_r|_calloc_r|_realloc_r|_sbrk|_sbrk_r|sbrk)$"
  "operator new/delete=^_Z(nw|na|dl|da)"
  "exceptions/RTTI=^(__cxa_(throw|allocate_exception|begin_catch|end_catch|rethrow|pure_virtual_called|bad_cast|bad_typeid)|__gxx_personality|_Unwind_|__aeabi_unwind_cpp_pr|_ZTI|_ZTS)"
  "stdio=^(printf|sprintf|snprintf|vfprintf|_vfprintf_r|_svfprintf_r|_dtoa_r)$")

set(found "")
string(REPLACE "\n" ";" lines "${syms}")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "^[0-9a-fA-F]+ [A-Za-z] " "" name "${line}")
  if(name STREQUAL "" OR name STREQUAL line)
    continue()
  endif()
  if(ALLOW AND name MATCHES "${ALLOW}")
    continue()
  endif()
  foreach(f IN LISTS families)
    string(REGEX REPLACE "=.*" "" why "${f}")
    string(REGEX REPLACE "^[^=]*=" "" re "${f}")
    if(name MATCHES "${re}")
      list(APPEND found "  ${name}  (${why})")
    endif()
  endforeach()
endforeach()

if(found)
  list(REMOVE_DUPLICATES found)
  string(REPLACE ";" "\n" found_text "${found}")
  set(why_text "")
  if(MAP AND EXISTS ${MAP})
    # The map's first section says which object pulled each library member in:
    #   <library>(<member>)
    #                     <requesting object> (<symbol>)
    file(READ ${MAP} map)
    string(FIND "${map}" "\nDiscarded input sections" cut)
    if(cut GREATER 0)
      string(SUBSTRING "${map}" 0 ${cut} map)
    endif()
    string(REPLACE ";" "," map "${map}")
    string(REPLACE "\n" ";" map_lines "${map}")
    set(member "")
    foreach(l IN LISTS map_lines)
      if(l MATCHES "^[^ ].*\\.a\\(.*\\)$")
        set(member "${l}")
      elseif(l MATCHES "^ +([^ ]+) \\(([^)]+)\\)$")
        set(req "${CMAKE_MATCH_1}")
        set(sym "${CMAKE_MATCH_2}")
        if(found MATCHES " ${sym} ")
          get_filename_component(req "${req}" NAME)
          get_filename_component(mem "${member}" NAME)
          string(APPEND why_text "\n  ${sym}: ${req} pulled in ${mem}")
        endif()
      endif()
    endforeach()
    if(why_text)
      set(why_text "\nWho pulled them in (from ${MAP}):${why_text}")
    endif()
  endif()
  message(FATAL_ERROR "${ELF}: forbidden symbols linked in:\n${found_text}${why_text}")
endif()
message(STATUS "${ELF}: no soft-float, libm, heap, new/delete, exception or stdio symbols")
