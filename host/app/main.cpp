// vkphoton's entry point: the command line is host/app/cli.h.
#include "app/cli.h"

int main(int argc, char** argv) { return vkp::runCommandLine(argc, argv); }
