#pragma once
// One message about a scene file: where (file, 1-based line and column), which key and
// what is wrong. Formats as the compiler-style "file:line:col: error: message".

#include <string>
#include <vector>

namespace throng::sim {

enum class Severity { Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;
    int line = 0;    // 1-based; 0 = the file as a whole
    int column = 0;  // 1-based; 0 = the line as a whole
    std::string key; // dotted key path, e.g. "agent_types[2].radius"; may be empty
    std::string message;

    std::string format() const;
};

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

}  // namespace throng::sim
