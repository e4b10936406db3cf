#include "editor/ScreenshotCommand.h"

#include "editor/viewport/Viewport.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QFileInfo>
#include <QImage>

#include <exception>
#include <memory>
#include <ostream>

namespace throng::editor {

ScreenshotCommand::ScreenshotCommand(ScreenshotOptions options, std::ostream& out, std::ostream& err)
    : m_options(std::move(options)), m_out(out), m_err(err)
{
}

int ScreenshotCommand::run()
{
    const sim::LoadResult loaded = sim::loadScene(QFile::encodeName(m_options.scenePath).toStdString());
    for (const sim::Diagnostic& d : loaded.diagnostics)
        m_err << d.format() << '\n';
    if (!loaded.ok())
        return 1;

    std::unique_ptr<sim::World> world;
    try {
        world = std::make_unique<sim::World>(loaded.scene);
        for (int i = 0; i < m_options.frame; ++i)
            world->step();
    } catch (const std::exception& e) {
        m_err << m_options.scenePath.toStdString() << ": error: the simulation failed: " << e.what() << '\n';
        return 1;
    }

    // A shown widget that never reaches the screen still renders into its framebuffer.
    Viewport viewport;
    viewport.setAttribute(Qt::WA_DontShowOnScreen);
    viewport.resize(m_options.sizePx);
    viewport.setViewMode(m_options.view);
    viewport.setAgentsAsCharacters(true);
    viewport.setSceneDirectory(QFileInfo(m_options.scenePath).absolutePath());
    viewport.setScene(loaded.scene, *world);
    viewport.show();
    const QImage image = viewport.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
    if (!viewport.isGlReady()) {
        m_err << "throng: error: cannot render: " << viewport.glProblem().toStdString() << '\n';
        return 1;
    }
    if (image.isNull() || !image.save(m_options.outputPath)) {
        m_err << m_options.outputPath.toStdString()
              << ": error: cannot write the image (is the folder writable and the suffix .png?)\n";
        return 1;
    }
    m_out << m_options.outputPath.toStdString() << '\n';
    return 0;
}

}  // namespace throng::editor
