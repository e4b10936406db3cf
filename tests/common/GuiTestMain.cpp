// main() for test executables that drive widgets (editor): needs a display (xvfb-run -a).
#include "TestRegistry.h"

#include <QApplication>
#include <QStandardPaths>
#include <QTemporaryDir>

int main(int argc, char** argv)
{
    // Every test process gets a home of its own: QSettings and QStandardPaths (in test mode
    // too, ~/.qttest) write under it, so test classes that run side by side (ctest -j) never
    // read each other's saved settings (a viewport overlay one turned on, a colouring
    // another remembered). Removed when the process ends.
    QTemporaryDir home;
    if (home.isValid())
        qputenv("HOME", home.path().toLocal8Bit());
    QApplication app(argc, argv);
    // Settings and standard paths in test mode, under the tests' organisation; each test
    // class runs under its own application name (runRegisteredTests), so no test class
    // sees what another saved even within one process.
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("ThrongTests");
    return throng::test::runRegisteredTests(argc, argv);
}
