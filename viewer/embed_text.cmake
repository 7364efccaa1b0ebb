# Writes OUTPUT, a C++ file that defines `const char* const NAME_parts[]` (null-ended) holding
# the text of INPUT in raw string literals of at most 60000 characters each (ISO C++ asks
# compilers to support 65536), so the program carries the file. Run with cmake -P.
file(READ "${INPUT}" text)
set(delimiter "airshape_text")
string(FIND "${text}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} holds the raw string delimiter ${delimiter}")
endif()
string(LENGTH "${text}" length)
set(out "// Generated from ${INPUT} by viewer/embed_text.cmake; do not edit.\nnamespace airshape::viewer::resources {\nextern const char* const ${NAME}_parts[];\nconst char* const ${NAME}_parts[] = {\n")
set(start 0)
while(start LESS length)
  string(SUBSTRING "${text}" ${start} 60000 part)
  string(APPEND out "R\"${delimiter}(${part})${delimiter}\",\n")
  math(EXPR start "${start} + 60000")
endwhile()
string(APPEND out "nullptr};\n}  // namespace airshape::viewer::resources\n")
file(WRITE "${OUTPUT}" "${out}")
