# clips_raw_string(OUT CONTENT DELIM SOURCE): sets OUT to CONTENT as C++ raw
# string literals R"DELIM(...)DELIM", one per 8000 characters (compilers
# limit the length of one literal; adjacent literals are joined). SOURCE
# names the file in the error raised when CONTENT holds the closing delimiter.
function(clips_raw_string out content delim source)
  string(FIND "${content}" ")${delim}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${source} contains the raw-string delimiter )${delim}\"")
  endif()
  string(LENGTH "${content}" len)
  set(pieces "")
  set(pos 0)
  while(pos LESS len)
    string(SUBSTRING "${content}" ${pos} 8000 chunk)
    string(APPEND pieces "R\"${delim}(${chunk})${delim}\"\n")
    math(EXPR pos "${pos} + 8000")
  endwhile()
  set(${out} "${pieces}" PARENT_SCOPE)
endfunction()
