#include "k923/keyboard_map_dialog.h"

#include "k923/key_face.h"
#include "k923/key_map.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QShowEvent>
#include <QTableWidget>
#include <QVBoxLayout>

namespace k528::studio {

using panel::Key;
using panel::KeyPress;

KeyboardMapDialog::KeyboardMapDialog(QWidget* parent) : QDialog(parent) {
    setObjectName("k923.keyboardMap");
    intro_ = new QLabel(this);
    intro_->setWordWrap(true);
    table_ = new QTableWidget(this);
    table_->setColumnCount(3);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setWordWrap(true);
    // Wrapped descriptions need their rows re-measured when the width changes.
    connect(table_->horizontalHeader(), &QHeaderView::sectionResized, table_,
            [this] { table_->resizeRowsToContents(); });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro_);
    layout->addWidget(table_, 1);
    layout->addWidget(buttons);
    resize(760, 620);
    fill();
}

void KeyboardMapDialog::fill() {
    setWindowTitle(tr("K923 keyboard map"));
    intro_->setText(
        tr("The PC keyboard works the panel while the panel has the focus: click the panel "
           "(a ring shows round it) or reach it with Tab; Tab leaves it again. Shift held with a "
           "PC key that is not a character gives SHIFT+key; S latches the panel's SHIFT for the "
           "next key, as a click on SHIFT does. Letters work in the Russian layout too."));
    table_->setHorizontalHeaderLabels({tr("Panel key"), tr("PC keyboard"), tr("Function")});
    table_->setRowCount(0);
    const auto addRow = [this](const QString& panelKey, const QStringList& pc,
                               const QString& what) {
        const int row = table_->rowCount();
        table_->insertRow(row);
        table_->setItem(row, 0, new QTableWidgetItem(panelKey));
        table_->setItem(row, 1, new QTableWidgetItem(pc.join(QStringLiteral(", "))));
        table_->setItem(row, 2, new QTableWidgetItem(what));
    };
    for (int i = 0; i < panel::kKeyCount; ++i) {
        const Key k = static_cast<Key>(i);
        addRow(keyTitle(k), pcKeysFor({k, false}), keyDescription(k));
        const QStringList shifted = pcKeysFor({k, true});
        if (!shifted.isEmpty())
            addRow(QStringLiteral("SHIFT+") + keyTitle(k), shifted, shiftedDescription(k));
    }
    table_->resizeColumnToContents(0);
    table_->resizeColumnToContents(1);
    table_->resizeRowsToContents();
}

void KeyboardMapDialog::showEvent(QShowEvent* event) {
    QDialog::showEvent(event);
    table_->resizeRowsToContents();
}

void KeyboardMapDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        fill();
    QDialog::changeEvent(event);
}

} // namespace k528::studio
