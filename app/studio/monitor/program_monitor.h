// The program the controller runs, as an operator follows it beside the
// machine: the frames of the program in canonical text, the frame being
// executed marked and kept in view, and above them the program, its state,
// the frame number and the technological message. Read-only. It follows the
// executing program (R253: a subprogram while it runs), else the one
// selected for АВТОМАТ (R252), else the catalog's first; the trainer may pin
// another one.
#pragma once

#include <QWidget>
#include <cstdint>

class QComboBox;
class QLabel;
class QListWidget;

namespace k528::studio {

class Controller;

class ProgramMonitor : public QWidget {
    Q_OBJECT
public:
    explicit ProgramMonitor(Controller& controller, QWidget* parent = nullptr);
    // Follows another controller (the simulated one, or the link's).
    void setController(Controller& controller);

    // The program shown (0: none), and the row marked as executing (-1: none).
    int shownProgram() const { return shown_; }
    int executingRow() const { return marked_; }
    QListWidget* frames() const { return list_; }
    QComboBox* programChoice() const { return choice_; }

public slots:
    void refresh();

protected:
    void changeEvent(QEvent* event) override;

private:
    void fillChoice();
    void showProgram(int number);
    void retranslate();

    Controller* controller_ = nullptr;
    QComboBox* choice_ = nullptr; // "follow the controller", then L1..L99
    QLabel* status_ = nullptr;
    QListWidget* list_ = nullptr;
    int shown_ = 0;
    int marked_ = -1;
    std::uint64_t revision_ = ~std::uint64_t{0};
    QString statusText_;
};

} // namespace k528::studio
