# Lists the functions and variables that cg's public headers declare, one name
# a line, in OUTPUT (the names libcg may export), and writes the linker version
# script VERSION_SCRIPT that exports exactly those from libcg.so.
#   cmake -DHEADERS="a.h;b.h" -DOUTPUT=public.txt -DVERSION_SCRIPT=libcg.map -P public_symbols.cmake
#
# A declaration is found after comments, preprocessor lines and every {...}
# block (struct and enum bodies, static inline function bodies) are removed:
# what is left splits at ';' into declarations, and a declaration that is not a
# typedef and not static names its function (cg_name followed by '(') or its
# variable (an extern cg_name).  Static inline functions are not exported.
set(names "")
foreach(header IN LISTS HEADERS)
  if(NOT header)
    continue()
  endif()
  file(READ ${header} text)
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" " " text "${text}")
  string(REGEX REPLACE "//[^\n]*" " " text "${text}")
  # The C++ linkage wrapper (extern "C" { ... }) is not a block to remove.
  string(REGEX REPLACE "#ifdef __cplusplus[^#]*#endif" " " text "${text}")
  # Preprocessor lines, including continued ones.
  string(REGEX REPLACE "\\\\\n" " " text "${text}")
  string(REGEX REPLACE "(^|\n)[ \t]*#[^\n]*" "\n" text "${text}")
  # Innermost blocks first, until none is left; each ends a declaration.
  set(previous "")
  while(NOT text STREQUAL previous)
    set(previous "${text}")
    string(REGEX REPLACE "{[^{}]*}" ";" text "${text}")
  endwhile()
  string(REPLACE "\n" " " text "${text}")
  # ';' separates the list elements CMake iterates over; brackets would group.
  string(REPLACE "[" " " text "${text}")
  string(REPLACE "]" " " text "${text}")
  foreach(declaration IN LISTS text)
    if(declaration MATCHES "(^|[^a-zA-Z0-9_])(typedef|static)[^a-zA-Z0-9_]")
      continue()
    endif()
    if(declaration MATCHES "(^|[^a-zA-Z0-9_])(cg_[a-zA-Z0-9_]*)[ \t]*\\(")
      list(APPEND names ${CMAKE_MATCH_2})
    elseif(declaration MATCHES "(^|[ \t])extern[ \t].*[^a-zA-Z0-9_](cg_[a-zA-Z0-9_]*)[ \t]*$")
      list(APPEND names ${CMAKE_MATCH_2})
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES names)
list(SORT names)
list(LENGTH names count)
if(count EQUAL 0)
  message(FATAL_ERROR "public_symbols: no declaration found in ${HEADERS}")
endif()
string(REPLACE ";" "\n" lines "${names}")
set(map "/* Generated from cg's public headers by cmake/public_symbols.cmake: libcg.so\n   exports exactly the functions and variables they declare. */\n{\n  global:\n")
foreach(name IN LISTS names)
  string(APPEND map "    ${name};\n")
endforeach()
string(APPEND map "  local:\n    *;\n};\n")
# Rewritten only when different, so that the libraries relink only then.
function(write_if_changed path content)
  set(old "")
  if(EXISTS ${path})
    file(READ ${path} old)
  endif()
  if(NOT old STREQUAL content)
    file(WRITE ${path} "${content}")
  endif()
endfunction()
write_if_changed(${OUTPUT} "${lines}\n")
write_if_changed(${VERSION_SCRIPT} "${map}")
