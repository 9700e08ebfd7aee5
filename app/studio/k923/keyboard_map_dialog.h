// "Keyboard map": every K923 key, the PC keys that press it and what it does.
#pragma once

#include <QDialog>

class QTableWidget;
class QLabel;

namespace k528::studio {

class KeyboardMapDialog : public QDialog {
    Q_OBJECT
public:
    explicit KeyboardMapDialog(QWidget* parent = nullptr);

    QTableWidget* table() const { return table_; }

protected:
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void fill();

    QLabel* intro_ = nullptr;
    QTableWidget* table_ = nullptr;
};

} // namespace k528::studio
