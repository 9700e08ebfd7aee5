// What the panes of a controller's parameters share (the machine constants,
// constants_dock.h, and the R-parameters, rparams_dock.h): a search field
// with the pane's own choices beside it, a row of tool buttons that wraps in
// a narrow dock with the note for the next revision at its end, the table
// (a row selected at a time, edited where the model allows), the status line
// kept in view below it, the values following the controller the window
// shows, the texts given again on a change of the language, and their docks
// (addParameterTableDock()) with the notice of a controller on the line.
#pragma once

#include "controller/controller.h"

#include <QString>
#include <QWidget>
#include <initializer_list>
#include <vector>

class QDockWidget;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QMainWindow;
class QTableView;
class QToolButton;

namespace k528::studio {

class ParameterFilter;
class ParameterTableModel;

class ParameterTablePane : public QWidget {
    Q_OBJECT
public:
    QTableView* table() const { return table_; }
    QLineEdit* searchField() const { return search_; }
    QLineEdit* noteField() const { return note_; }
    // The last refusal or confirmation shown under the table.
    QString statusText() const;
    // Shows `text` there (red: a refusal).
    void say(const QString& text, bool bad);

    // The dock's title; of a controller on the line, how its parameters are
    // read and how a change is written to it (when it may be written now).
    QString dockTitle() const;
    QString lineReading() const;
    QString lineWriting() const;

protected:
    // Those three texts as the pane marks them (QT_TR_NOOP: translated in its context).
    struct DockTexts {
        const char* title;
        const char* reading;
        const char* writing;
    };
    // `prefix`: the first part of its widgets' object names ("constants" →
    // constants.search, …) and the dock's (dock.constants); `area`: the
    // controller's memory the parameters are in.
    ParameterTablePane(ViewedController& viewed, const QString& prefix, MemoryArea area, DockTexts texts,
                       QWidget* parent);
    // A tool button named `<prefix>.<name>`, for build(), saying `text`
    // with `toolTip` (marked with QT_TR_NOOP in the pane: translated in its
    // context, again on each change of the language).
    QToolButton* toolButton(const char* name, const char* text, const char* toolTip = nullptr);
    // The pane's layout: the search field then `choices` on top, `tools`
    // and the note, the table over `filter` (whose source is `model`; its
    // columns `columnEms` wide, in widths of an M), the status line (and
    // `statusExtras` after it); the model follows the controller from now on.
    void build(ParameterTableModel* model, ParameterFilter* filter, std::initializer_list<QWidget*> choices,
               std::initializer_list<QToolButton*> tools, std::initializer_list<int> columnEms,
               std::initializer_list<QWidget*> statusExtras = {});
    // The selected parameter's number, -1 when none.
    int selectedNumber() const;
    // Selects and shows the row of the model's `source` index.
    void selectSource(const QModelIndex& source);
    // All the pane's texts in the UI's language: its tool buttons', the
    // pane's own (retranslatePane()), the note's, the model's.
    void retranslate();
    virtual void retranslatePane() = 0;
    void changeEvent(QEvent* e) override;

    ViewedController& viewed_;
    QLineEdit* note_ = nullptr;

private:
    friend QDockWidget* addParameterTableDock(QMainWindow* window, ParameterTablePane* pane);
    void followController();
    // Each column at least as wide as its title.
    void fitHeaders();
    QString prefix_;
    MemoryArea area_;
    DockTexts dockTexts_;
    // The tool buttons' texts as the pane marks them (toolButton()).
    struct ToolText {
        QToolButton* button;
        const char* text;
        const char* toolTip;
    };
    std::vector<ToolText> toolTexts_;
    // One of the pane's own texts (marked with QT_TR_NOOP) in the UI's language.
    QString paneText(const char* text) const;
    QMetaObject::Connection updates_;
    ParameterTableModel* model_ = nullptr;
    ParameterFilter* filter_ = nullptr;
    QLineEdit* search_ = nullptr;
    QLabel* noteLabel_ = nullptr;
    QTableView* table_ = nullptr;
    QLabel* status_ = nullptr;
};

// Adds the dock of `pane` (left area, hidden until chosen from the View
// menu; the workspaces place it), with the notice above the pane of a
// controller on the line: how it is read, then how it is written or why
// it cannot be now.
QDockWidget* addParameterTableDock(QMainWindow* window, ParameterTablePane* pane);

} // namespace k528::studio
