// A view's notice about the controller it shows (controller/controller.h):
// a line above the view's content that says what this controller cannot
// give and why (the content greyed: Unavailable), that its values are the
// last read before the line went quiet (Stale), or how its values may be
// changed (Info). No notice: the line is hidden.
#pragma once

#include <QWidget>
#include <functional>
#include <utility>

class QLabel;
class QScrollArea;

namespace k528::studio {

class Controller;
class ViewedController;

class ViewNotice : public QWidget {
    Q_OBJECT
public:
    enum class Level { None, Info, Stale, Unavailable };

    // Wraps `content` (it becomes a child) under the notice line.
    explicit ViewNotice(QWidget* content, QWidget* parent = nullptr);
    QWidget* content() const { return content_; }
    QLabel* label() const { return label_; }
    Level level() const { return level_; }
    QString text() const;
    void setNotice(Level level, const QString& text = {});
    // Stale when `c` has lost its line, else `level` and `text`.
    void setNotice(const Controller& c, Level level, const QString& text = {});

    // Keeps the notice of the controller `viewed` shows: `what` says it
    // (called when another controller is shown and on each of its updates;
    // a lost line is said by the notice itself).
    using Say = std::function<std::pair<Level, QString>(Controller&)>;
    void follow(ViewedController& viewed, Say what);
    void refresh();
    // The content scrolls under the notice line (the notice stays in view
    // and wraps to the dock's width): for a dock whose content cannot shrink.
    void scrollContent();

protected:
    void changeEvent(QEvent* e) override;

private:
    QWidget* content_;
    ViewedController* viewed_ = nullptr;
    Say say_;
    QMetaObject::Connection updates_;
    QLabel* label_;
    Level level_ = Level::None;
    QScrollArea* scroll_ = nullptr;
    class Veil;
    Veil* veil_ = nullptr;
};

} // namespace k528::studio
