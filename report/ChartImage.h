#pragma once
// Renders a Qt chart to an image without a window (the CLI's report, and tests), and
// makes sure a QApplication exists to do it with: a command-line program gets one on
// the offscreen platform. Never shows anything.

#include <QImage>
#include <QSize>

class QChart;

namespace throng::report {

// Creates a QApplication on the offscreen platform (unless QT_QPA_PLATFORM names one)
// when the program has none; Qt Charts needs one. Call from the main thread. False when
// the program runs a QCoreApplication or QGuiApplication, which cannot draw charts.
bool ensureApplication();

QImage renderChart(QChart& chart, QSize size);

}  // namespace throng::report
