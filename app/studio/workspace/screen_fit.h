// Keeping the main window inside its screen: a dock's content that cannot
// shrink scrolls inside the dock instead of widening the window, and the
// window's size and place are held inside the screen's available area.
#pragma once

#include <QRect>

class QDockWidget;
class QScrollArea;
class QWidget;

namespace k528::studio {

// Wraps `dock`'s content in a frameless scroll area that resizes it: the
// dock's minimum becomes the scroll area's (a few lines), the content keeps
// its own and scrolls when the dock is smaller. Returns the scroll area
// (object name "<dock>.scroll"); a content that already scrolls (an item
// view, a scroll area, a text editor) is left as it is (nullptr).
// A child of the content with the property kKeptInView set (its status line:
// a refusal, a revision notice) is taken out of it and kept below the scroll
// area, always in view at the dock's bottom ("<dock>.frame" holds both).
QScrollArea* scrollInside(QDockWidget* dock);
inline constexpr const char* kKeptInView = "k528KeptInView";
// The child of `content` marked kKeptInView, taken out of it into a new
// widget of `parent` (with the content's side and bottom margins) to be laid
// out below the scroll area; nullptr when it has none.
QWidget* takeKeptInView(QWidget* content, QWidget* parent);

// The available area (without panels and task bars) of the screen `w` is on,
// in logical pixels; the primary screen's when it has none yet.
QRect availableArea(const QWidget* w);

// `window` moved and resized so that its frame lies inside `area`.
void keepInside(QWidget* window, const QRect& area);

} // namespace k528::studio
