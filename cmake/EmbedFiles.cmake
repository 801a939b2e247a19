# Embeds text files into a C++ source as a table of (file name, contents) string views, so the
# binary needs no data files at run time. Run as a script:
#   cmake -DOUT=table.cpp -DNAME=identifier -DFILES="a|b" -P EmbedFiles.cmake
# (FILES separated by "|": a ";" would split the argument of add_custom_command).
# The contents go in as hex bytes (no escaping questions, any size).
set(content "#include <string_view>\n#include <utility>\nnamespace vkp::embedded {\n")
set(entries "")
string(REPLACE "|" ";" FILES "${FILES}")
set(index 0)
foreach(file IN LISTS FILES)
  get_filename_component(file_name ${file} NAME)
  file(READ ${file} hex HEX)
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
  string(APPEND content "static const char ${NAME}_${index}[] = {${bytes} 0};\n")
  string(APPEND entries "  {\"${file_name}\", std::string_view(${NAME}_${index}, sizeof(${NAME}_${index}) - 1)},\n")
  math(EXPR index "${index} + 1")
endforeach()
string(APPEND content "extern const std::pair<std::string_view, std::string_view> ${NAME}[] = {\n${entries}  {{}, {}}};\n}\n")
file(WRITE ${OUT} "${content}")
