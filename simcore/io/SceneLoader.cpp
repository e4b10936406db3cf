#include "simcore/io/SceneIO.h"
#include "simcore/io/detail/SceneReader.h"
#include "simcore/io/detail/YamlDocument.h"

#include <filesystem>

namespace throng::sim {

namespace {

void readDocument(const YAML::Node& root, const std::string& text, const std::string& baseDir,
                  detail::YamlFields& fields, LoadResult& result)
{
    // A document of comments only, or a bare word, has no mark of its own: its start is
    // where the map should begin.
    const auto located = [](YAML::Mark m) {
        if (m.line < 0) {
            m.line = 0;
            m.column = 0;
        }
        return m;
    };
    if (!root.IsMap()) {
        fields.error(located(root.Mark()), "", "a scene file is a map of sections starting with 'throng: 1'");
        return;
    }
    try {
        detail::SceneReader reader(fields, baseDir, text);
        reader.read(root, result.scene);
    } catch (const YAML::Exception& e) {
        // The reader checks types before converting; this is a last line of defence.
        fields.error(located(e.mark), "", "unexpected YAML structure: " + e.msg);
    }
}

}  // namespace

LoadResult parseScene(const std::string& text, const std::string& fileName, const std::string& baseDir)
{
    LoadResult result;
    detail::YamlFields fields(fileName, result.diagnostics);
    YAML::Node root;
    if (detail::parseYamlText(text, fields, root))
        readDocument(root, text, baseDir, fields, result);
    if (!result.ok())
        result.scene = Scene{};
    return result;
}

LoadResult loadScene(const std::string& path)
{
    LoadResult result;
    detail::YamlFields fields(path, result.diagnostics);
    std::string text;
    YAML::Node root;
    if (detail::readYamlFile(fields, text, root))
        readDocument(root, text, std::filesystem::path(path).parent_path().string(), fields, result);
    if (!result.ok())
        result.scene = Scene{};
    return result;
}

}  // namespace throng::sim
