#pragma once
// The editor's one dark theme: Fusion with a palette whose window is the viewport's clear
// colour and whose highlight is its selection yellow, plus a short stylesheet for what
// the palette cannot reach. Changes only application-wide style state, never a widget.

#include <QColor>

class QApplication;

namespace throng::editor {

struct DarkThemeColours {
    QColor window;     // the viewport's clear colour (palette::kBackground)
    QColor base;       // the brain editor's canvas: lists, fields, views
    QColor panel;      // buttons, dock title bars, tool tips
    QColor text;
    QColor disabledText;
    QColor highlight;  // the viewport's selection yellow
    QColor highlightedText;
    QColor link;       // the viewport's path blue
    QColor separator;
};

const DarkThemeColours& darkThemeColours();

// Sets Fusion, the dark palette (tool tips included) and the stylesheet on `app`.
void applyDarkTheme(QApplication& app);

}  // namespace throng::editor
