#include "TestRegistry.h"

#include <QCoreApplication>
#include <QTest>

#include <cstring>
#include <iostream>

namespace throng::test {

std::vector<RegisteredTest>& registeredTests()
{
    static std::vector<RegisteredTest> tests;
    return tests;
}

bool registerTest(const char* name, TestFactory make)
{
    registeredTests().push_back({name, std::move(make)});
    return true;
}

int runRegisteredTests(int argc, char** argv)
{
    std::string only;
    std::vector<char*> args{argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (only.empty() && argv[i][0] != '-' && std::strncmp(argv[i], "Test", 4) == 0)
            only = argv[i];
        else
            args.push_back(argv[i]);
    }
    int failures = 0;
    bool found = false;
    for (const RegisteredTest& t : registeredTests()) {
        if (!only.empty() && t.name != only)
            continue;
        found = true;
        QCoreApplication::setApplicationName(QString::fromStdString(t.name));  // its settings apart
        std::unique_ptr<QObject> object = t.make();
        failures += QTest::qExec(object.get(), int(args.size()), args.data());
    }
    if (!found) {
        std::cerr << "no test class named '" << only << "'; known:";
        for (const RegisteredTest& t : registeredTests())
            std::cerr << ' ' << t.name;
        std::cerr << '\n';
        return 2;
    }
    return failures == 0 ? 0 : 1;
}

}  // namespace throng::test
