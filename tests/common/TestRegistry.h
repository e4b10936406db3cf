#pragma once
// Lets each QtTest class in a module's test executable register itself, so the one
// executable can run one class by name (one CTest entry per class) or all of them.

#include <QObject>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace throng::test {

using TestFactory = std::function<std::unique_ptr<QObject>()>;
struct RegisteredTest {
    std::string name;
    TestFactory make;
};
std::vector<RegisteredTest>& registeredTests();
bool registerTest(const char* name, TestFactory make);
// Runs the class named argv[1] (or every class when none is named) with QTest.
int runRegisteredTests(int argc, char** argv);

}  // namespace throng::test

#define THRONG_REGISTER_TEST(Class) \
    static const bool kRegistered##Class = \
        throng::test::registerTest(#Class, [] { return std::unique_ptr<QObject>(new Class); });
