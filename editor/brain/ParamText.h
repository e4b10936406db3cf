#pragma once
// Turns what the user typed into a node parameter (a number, a list of numbers, a name
// or a choice), checked against the catalogue's ParamSpec. Pure text handling.

#include "simcore/brain/NodeCatalogue.h"
#include "simcore/scene/BrainGraph.h"

#include <QString>

namespace throng::editor {

// Fills `param` from `text`; returns why the text is not a valid value, empty when it is.
QString parseParamText(const sim::ParamSpec& spec, const QString& text, sim::BrainParam& param);

}  // namespace throng::editor
