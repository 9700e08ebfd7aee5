// Teach-in (NC-200 §20) into the editor's current document: the viewed
// controller's position (its current coordinates as the panel shows them)
// as a frame after the cursor's line, numbered after it; or into a preset
// R-parameter whose hint names that coordinate (editing/teach.h), replacing
// the cursor's line when it sets that R.
#pragma once

#include <QObject>

class QMenu;

namespace k528::studio {

class EditorTab;
class ViewedController;

class TeachIn : public QObject {
    Q_OBJECT
public:
    TeachIn(EditorTab& tab, ViewedController* viewed);

    // False (and a status message) when no document, no controller or no
    // axis. The text inserted is returned through `taught`.
    bool teachPosition(QString* taught = nullptr);
    bool teachIntoR(int r, QString* taught = nullptr);
    // `menu` anew: an action a teachable R-parameter.
    void fillTargetsMenu(QMenu* menu);

signals:
    void statusMessage(const QString& text);

private:
    bool insertTaught(const QString& text, bool replaceLine);
    int frameNumberAtCursor() const;
    EditorTab& tab_;
    ViewedController* viewed_ = nullptr;
};

} // namespace k528::studio
