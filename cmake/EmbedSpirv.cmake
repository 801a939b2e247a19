# Script mode: turns one .spv file into a C++ source defining its words and a (name, span) pair.
file(READ ${SPV} hex HEX)
# SPIR-V words are stored little-endian: swap each group of four bytes into a 0x........u literal.
string(REGEX REPLACE "([0-9a-f][0-9a-f])([0-9a-f][0-9a-f])([0-9a-f][0-9a-f])([0-9a-f][0-9a-f])"
       "0x\\4\\3\\2\\1u,\n" body "${hex}")
file(WRITE ${OUT} "#include <cstdint>\n#include <span>\n#include <string_view>\n#include <utility>\n"
  "namespace vkp::embedded {\nstatic const uint32_t ${IDENT}_words[] = {\n${body}};\n"
  "extern const std::pair<std::string_view, std::span<const uint32_t>> ${IDENT}{\"${NAME}\", ${IDENT}_words};\n}\n")
