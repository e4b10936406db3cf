// main() for test executables that need no GUI (simcore, export, cli).
#include "TestRegistry.h"

#include <QCoreApplication>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    return throng::test::runRegisteredTests(argc, argv);
}
