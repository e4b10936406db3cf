#include "Cli.h"

#include <iostream>

int main(int argc, char** argv)
{
    return throng::cli::runCli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
