#include "simcore/io/detail/YamlDocument.h"

#include "simcore/io/SceneIO.h"

#include <filesystem>
#include <fstream>

namespace throng::sim::detail {

namespace {

// Finds the first byte that cannot be in a text file (NUL, a control character, or
// invalid UTF-8), so binary garbage is refused with a location before the parser sees it.
bool findBinary(const std::string& text, int& line1, int& col1)
{
    line1 = 1;
    col1 = 1;
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        int extra = 0;
        if (c == '\n') {
            ++line1;
            col1 = 1;
            ++i;
            continue;
        }
        if (c == 0 || (c < 0x20 && c != '\t' && c != '\r'))
            return true;
        if (c >= 0x80) {
            if ((c & 0xE0) == 0xC0 && c >= 0xC2) extra = 1;
            else if ((c & 0xF0) == 0xE0) extra = 2;
            else if ((c & 0xF8) == 0xF0 && c <= 0xF4) extra = 3;
            else return true;
            if (i + std::size_t(extra) >= text.size())
                return true;
            for (int k = 1; k <= extra; ++k)
                if ((static_cast<unsigned char>(text[i + std::size_t(k)]) & 0xC0) != 0x80)
                    return true;
        }
        i += std::size_t(1 + extra);
        ++col1;
    }
    return false;
}

// YAML forbids tabs in indentation; find one so we can say so plainly instead of the
// parser's guess. Whitespace-only lines may hold tabs.
bool findTabIndent(const std::string& text, int& line1, int& col1)
{
    for (std::size_t pos = 0, lineNo = 1; pos < text.size(); ++lineNo) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos)
            end = text.size();
        std::size_t i = pos;
        while (i < end && text[i] == ' ')
            ++i;
        if (i < end && text[i] == '\t' && text.find_first_not_of(" \t\r", i) < end) {
            line1 = int(lineNo);
            col1 = int(i - pos) + 1;
            return true;
        }
        pos = end + 1;
    }
    return false;
}

}  // namespace

bool parseYamlText(const std::string& text, YamlFields& f, YAML::Node& root)
{
    int line = 0, col = 0;
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
        f.errorAtLine(0, 0, "", "the file is empty");
        return false;
    }
    if (findBinary(text, line, col)) {
        f.errorAtLine(line, col, "", "the file is not UTF-8 text (binary data); is this the right file?");
        return false;
    }
    if (findTabIndent(text, line, col)) {
        f.errorAtLine(line, col, "", "a tab is used for indentation; YAML indents with spaces only");
        return false;
    }
    try {
        const bool bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
        root = YAML::Load(bom ? text.substr(3) : text);
    } catch (const YAML::Exception& e) {
        f.error(e.mark, "", "malformed YAML: " + e.msg);
        return false;
    }
    return true;
}

bool readYamlFile(YamlFields& f, std::string& text, YAML::Node& root)
{
    namespace fs = std::filesystem;
    const std::string& path = f.file();
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
        f.errorAtLine(0, 0, "", "no such file");
        return false;
    }
    if (fs::is_directory(status)) {
        f.errorAtLine(0, 0, "", "is a directory, not a file");
        return false;
    }
    const auto size = fs::file_size(path, ec);
    if (ec) {
        f.errorAtLine(0, 0, "", "cannot read the file size: " + ec.message());
        return false;
    }
    if (size > kMaxSceneFileBytes) {
        f.errorAtLine(0, 0, "", "the file is " + std::to_string(size >> 20) + " MB; files are limited to " +
                                    std::to_string(kMaxSceneFileBytes >> 20) + " MB");
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    text.assign(size, '\0');
    if (!in || !in.read(text.data(), std::streamsize(size))) {
        f.errorAtLine(0, 0, "", "cannot read the file");
        return false;
    }
    return parseYamlText(text, f, root);
}

}  // namespace throng::sim::detail
