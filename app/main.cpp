#include "app/cli.h"

int main(int argc, char** argv) { return scatterlab::runCli(argc, argv); }
