#include "FileMutator.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

namespace throng::test {

namespace {

// SplitMix64: a counter-based generator whose sequence is fixed by the standard of
// arithmetic alone (std:: distributions differ between libraries).
class Draw {
public:
    explicit Draw(std::uint64_t state) : m_state(state) {}
    std::uint64_t next()
    {
        std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(next() % n); }

private:
    std::uint64_t m_state;
};

const std::array<const char*, 20> kNumbers = {
    "0", "-1", "1e30", "-1e30", "nan", ".nan", ".inf", "-.inf", "1e-30", "10000000", "4294967295", "4294967296",
    "18446744073709551616", "0.001", "1e9", "-0", "3.4e38", "2147483648", "1e6", "-1e6"};

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t end = text.find('\n', at);
        out.push_back(text.substr(at, end == std::string::npos ? std::string::npos : end - at));
        if (end == std::string::npos)
            break;
        at = end + 1;
    }
    return out;
}

std::string join(const std::vector<std::string>& ls)
{
    std::string s;
    for (std::size_t k = 0; k < ls.size(); ++k) {
        s += ls[k];
        if (k + 1 < ls.size())
            s += '\n';
    }
    return s;
}

// Lines that say something (not blank, not a comment): where mutations matter.
std::size_t pickLine(const std::vector<std::string>& ls, Draw& d)
{
    for (int tries = 0; tries < 16; ++tries) {
        const std::size_t k = d.below(ls.size());
        const std::size_t first = ls[k].find_first_not_of(' ');
        if (first != std::string::npos && ls[k][first] != '#')
            return k;
    }
    return d.below(ls.size());
}

// Offsets and lengths of the numbers in text: -?digits(.digits)?([eE][-+]?digits)?, not
// inside a word. (std::regex trips GCC 12's -Wmaybe-uninitialized under the sanitizers.)
std::vector<std::pair<std::size_t, std::size_t>> numbers(const std::string& t)
{
    const auto digit = [&](std::size_t i) { return i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); };
    const auto word = [&](std::size_t i) {
        return std::isalnum(static_cast<unsigned char>(t[i])) || t[i] == '_' || t[i] == '.';
    };
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t i = 0;
    while (i < t.size()) {
        const std::size_t start = i;
        std::size_t j = i + (t[i] == '-' ? 1 : 0);
        if (!digit(j) || (start > 0 && word(start - 1))) {
            ++i;
            continue;
        }
        while (digit(j))
            ++j;
        if (j < t.size() && t[j] == '.' && digit(j + 1))
            for (++j; digit(j); ++j) {}
        if (j < t.size() && (t[j] == 'e' || t[j] == 'E')) {
            std::size_t k = j + 1;
            if (k < t.size() && (t[k] == '-' || t[k] == '+'))
                ++k;
            if (digit(k))
                for (j = k; digit(j); ++j) {}
        }
        out.push_back({start, j - start});
        i = j;
    }
    return out;
}

std::string mutateOnce(const std::string& text, Draw& d, std::string& what)
{
    std::vector<std::string> ls = lines(text);
    if (ls.empty() || text.empty())
        return text;
    switch (d.below(9)) {
    case 0:
    case 1:
    case 2: {  // a number (the most common way a file goes wrong), three times as often
        const std::vector<std::pair<std::size_t, std::size_t>> at = numbers(text);
        if (at.empty())
            return text;
        const auto [pos, len] = at[d.below(at.size())];
        const std::string by = kNumbers[d.below(kNumbers.size())];
        what += "number '" + text.substr(pos, len) + "' at " + std::to_string(pos) + " -> " + by + "; ";
        return text.substr(0, pos) + by + text.substr(pos + len);
    }
    case 3: {
        const std::size_t k = pickLine(ls, d);
        what += "drop line " + std::to_string(k + 1) + "; ";
        ls.erase(ls.begin() + std::ptrdiff_t(k));
        return join(ls);
    }
    case 4: {  // a key or list item given again, or pasted many times
        const std::size_t k = pickLine(ls, d);
        const std::size_t copies = d.below(2) ? 1 : 1 + d.below(300);
        what += "repeat line " + std::to_string(k + 1) + " x" + std::to_string(copies) + "; ";
        ls.insert(ls.begin() + std::ptrdiff_t(k) + 1, copies, ls[k]);
        return join(ls);
    }
    case 5: {
        const std::size_t k = 1 + d.below(ls.size());
        what += "truncate after line " + std::to_string(k) + "; ";
        ls.resize(std::min(k, ls.size()));
        return join(ls);
    }
    case 6: {
        const std::size_t k = pickLine(ls, d);
        if (k + 1 >= ls.size())
            return text;
        what += "swap lines " + std::to_string(k + 1) + " and " + std::to_string(k + 2) + "; ";
        std::swap(ls[k], ls[k + 1]);
        return join(ls);
    }
    case 7: {
        static const std::string bytes = ":-[]{},#\"' \t|>&*!%@`\\0";
        const std::size_t at = d.below(text.size());
        const char c = bytes[d.below(bytes.size())];
        what += "byte " + std::to_string(at) + " -> '" + std::string(1, c) + "'; ";
        std::string t = text;
        t[at] = c;
        return t;
    }
    default: {  // a block of lines (a list item with its keys) pasted again
        const std::size_t k = pickLine(ls, d), n = 1 + d.below(6);
        const std::size_t end = std::min(ls.size(), k + n);
        const std::vector<std::string> block(ls.begin() + std::ptrdiff_t(k), ls.begin() + std::ptrdiff_t(end));
        const std::size_t copies = 1 + d.below(d.below(4) == 0 ? 2000 : 3);
        what += "repeat lines " + std::to_string(k + 1) + "-" + std::to_string(end) + " x" + std::to_string(copies) + "; ";
        for (std::size_t c = 0; c < copies; ++c)
            ls.insert(ls.begin() + std::ptrdiff_t(end), block.begin(), block.end());
        return join(ls);
    }
    }
}

}  // namespace

Mutant mutateText(const std::string& text, std::uint64_t seed, std::uint64_t index)
{
    Draw d(seed * 0x2545f4914f6cdd1dull + index * 0x9e3779b97f4a7c15ull + 1);
    Mutant m;
    m.text = text;
    const std::size_t ops = 1 + d.below(3);
    for (std::size_t k = 0; k < ops; ++k)
        m.text = mutateOnce(m.text, d, m.what);
    return m;
}

}  // namespace throng::test
