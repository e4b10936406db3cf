#pragma once
// A name like "wall_3" that no item of a scene list uses yet. Plain function.

#include <string>
#include <vector>

namespace throng::editor {

template <class T>
std::string uniqueName(const std::vector<T>& items, const std::string& stem)
{
    for (std::size_t n = items.size() + 1;; ++n) {
        const std::string name = stem + "_" + std::to_string(n);
        bool used = false;
        for (const T& item : items)
            used = used || item.name == name;
        if (!used)
            return name;
    }
}

}  // namespace throng::editor
