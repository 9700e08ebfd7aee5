// Live views of the controller for the docks "dock.messages" and
// "dock.axes", redrawn on Controller::updated() (only what changed): the
// simulated one or a real one on the link (controller/controller.h).
//
// MessagesView: the positioner's messages 1..64 (appendix М, in the UI
// language) and the PLC's machine alarms, system and work messages (the
// profile's texts), newest state first within each group.
//
// AxesView: per axis the current and machine positions, the rest of the
// path, the feed, the following error, the DAC, the reference and loop
// state; and the main bits of the interface words of appendix И.
#pragma once

#include <QWidget>
#include <vector>

class QTreeWidget;
class QTableWidget;
class QLabel;

namespace k528::studio {

class Controller;

class MessagesView : public QWidget {
    Q_OBJECT
public:
    explicit MessagesView(Controller& controller, QWidget* parent = nullptr);
    // Shows another controller (the simulated one, or the link's).
    void setController(Controller& controller);
    Controller& controller() const { return *controller_; }
    QTreeWidget* list() const { return list_; }
    QSize sizeHint() const override { return {640, 170}; }

public slots:
    void refresh();

protected:
    void changeEvent(QEvent*) override;

private:
    void retranslate();
    Controller* controller_ = nullptr;
    QTreeWidget* list_ = nullptr;
    QLabel* summary_ = nullptr;
    std::vector<QString> last_;
};

class AxesView : public QWidget {
    Q_OBJECT
public:
    explicit AxesView(Controller& controller, QWidget* parent = nullptr);
    // Shows another controller (the simulated one, or the link's).
    void setController(Controller& controller);
    Controller& controller() const { return *controller_; }
    QTableWidget* table() const { return table_; }
    QLabel* bits() const { return bits_; }
    QSize sizeHint() const override { return {640, 170}; }

public slots:
    void refresh();

protected:
    void changeEvent(QEvent*) override;

private:
    void retranslate();
    Controller* controller_ = nullptr;
    QTableWidget* table_ = nullptr;
    QLabel* bits_ = nullptr;
    QString lastBits_;
};

} // namespace k528::studio
