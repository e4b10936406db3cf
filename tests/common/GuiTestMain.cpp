// main() for test executables that drive widgets (editor): needs a display (xvfb-run -a).
#include "TestRegistry.h"

#include <QApplication>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    return throng::test::runRegisteredTests(argc, argv);
}
