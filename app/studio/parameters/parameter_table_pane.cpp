#include "parameters/parameter_table_pane.h"

#include "controller/view_notice.h"
#include "parameters/cell_text_delegate.h"
#include "parameters/parameter_table_model.h"
#include "widgets.h"
#include "workspace/flow_layout.h"
#include "workspace/pane_dock.h"
#include "workspace/screen_fit.h"

#include <QCoreApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace k528::studio {

ParameterTablePane::ParameterTablePane(ViewedController& viewed, const QString& prefix, MemoryArea area,
                                       DockTexts texts, QWidget* parent)
    : QWidget(parent), viewed_(viewed), prefix_(prefix), area_(area), dockTexts_(texts) {
    setObjectName(prefix + "Pane");
    search_ = new QLineEdit(this); // first in the focus chain, as on top
    search_->setObjectName(prefix + ".search");
    search_->setClearButtonEnabled(true);
}

QToolButton* ParameterTablePane::toolButton(const char* name, const char* text, const char* toolTip) {
    auto* b = new QToolButton(this);
    b->setObjectName(prefix_ + '.' + QLatin1String(name));
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    b->setAutoRaise(true);
    toolTexts_.push_back({b, text, toolTip});
    return b;
}

void ParameterTablePane::build(ParameterTableModel* model, ParameterFilter* filter,
                               std::initializer_list<QWidget*> choices, std::initializer_list<QToolButton*> tools,
                               std::initializer_list<int> columnEms, std::initializer_list<QWidget*> statusExtras) {
    model_ = model;
    filter_ = filter;
    filter_->setSourceModel(model_);

    auto* top = new QHBoxLayout;
    top->addWidget(search_, 1);
    for (QWidget* w : choices)
        top->addWidget(w);

    auto* toolRow = new FlowLayout; // wraps in a narrow dock: every button in reach
    for (QToolButton* b : tools)
        toolRow->addWidget(b);
    noteLabel_ = new QLabel(this);
    note_ = new QLineEdit(this);
    note_->setObjectName(prefix_ + ".note");
    note_->setMinimumWidth(180);
    toolRow->addGroup({noteLabel_, note_});

    table_ = new QTableView(this);
    table_->setObjectName(prefix_ + ".table");
    table_->setModel(filter_);
    // A search repaints the whole table: its texts are shaped once, not at every paint.
    table_->setItemDelegate(new CellTextDelegate(table_));
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::AnyKeyPressed);
    table_->setAlternatingRowColors(true);
    table_->setWordWrap(false);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->horizontalHeader()->setStretchLastSection(true);
    const int em = fontMetrics().horizontalAdvance(QLatin1Char('M'));
    int column = 0;
    for (int width : columnEms)
        table_->setColumnWidth(column++, width * em);
    fitHeaders();
    // A title is as long as its language makes it: Russian's are longer.
    // (The R-parameters' model says its new language by a reset.)
    connect(model_, &QAbstractItemModel::headerDataChanged, this, &ParameterTablePane::fitHeaders);
    connect(model_, &QAbstractItemModel::modelReset, this, &ParameterTablePane::fitHeaders);

    // The status line: kept in view below the table when the dock scrolls
    // (workspace/screen_fit.h).
    auto* statusRow = new QWidget(this);
    statusRow->setObjectName(prefix_ + ".statusRow");
    statusRow->setProperty(kKeptInView, true);
    auto* bottom = new QHBoxLayout(statusRow);
    bottom->setContentsMargins(0, 0, 0, 0);
    status_ = new QLabel(statusRow);
    status_->setObjectName(prefix_ + ".status");
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    bottom->addWidget(status_, 1);
    for (QWidget* w : statusExtras) {
        w->setParent(statusRow);
        bottom->addWidget(w);
    }

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addLayout(toolRow);
    layout->addWidget(table_, 1);
    layout->addWidget(statusRow);

    connect(search_, &QLineEdit::textChanged, filter_, &ParameterFilter::setSearch);
    connect(&viewed_, &ViewedController::changed, this, &ParameterTablePane::followController);
    followController();
}

void ParameterTablePane::fitHeaders() {
    // A column narrower than its title shows the title clipped at both ends;
    // widened, never narrowed, so a column the user made wider stays so.
    QHeaderView* header = table_->horizontalHeader();
    for (int c = 0; c < model_->columnCount(); ++c)
        if (header->sectionSize(c) < header->sectionSizeHint(c))
            header->resizeSection(c, header->sectionSizeHint(c));
}

void ParameterTablePane::followController() {
    disconnect(updates_);
    updates_ = connect(&viewed_.current(), &Controller::updated, model_, &ParameterTableModel::refresh);
    model_->refresh();
}

QString ParameterTablePane::paneText(const char* text) const {
    return QCoreApplication::translate(metaObject()->className(), text); // the pane's context, where it is marked
}

QString ParameterTablePane::dockTitle() const { return paneText(dockTexts_.title); }
QString ParameterTablePane::lineReading() const { return paneText(dockTexts_.reading); }
QString ParameterTablePane::lineWriting() const { return paneText(dockTexts_.writing); }

void ParameterTablePane::retranslate() {
    for (const ToolText& t : toolTexts_) {
        t.button->setText(paneText(t.text));
        if (t.toolTip)
            t.button->setToolTip(paneText(t.toolTip));
    }
    retranslatePane();
    noteLabel_->setText(tr("Note:"));
    model_->retranslate();
}

void ParameterTablePane::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void ParameterTablePane::say(const QString& text, bool bad) {
    showStatus(status_, text, bad);
}

QString ParameterTablePane::statusText() const {
    return status_->text();
}

int ParameterTablePane::selectedNumber() const {
    const QModelIndex i = table_->currentIndex();
    return i.isValid() ? i.data(ParameterTableModel::NumberRole).toInt() : -1;
}

void ParameterTablePane::selectSource(const QModelIndex& source) {
    const QModelIndex i = filter_->mapFromSource(source);
    if (i.isValid()) {
        table_->setCurrentIndex(i);
        table_->scrollTo(i);
    }
}

QDockWidget* addParameterTableDock(QMainWindow* window, ParameterTablePane* pane) {
    auto* dock = new PaneDock(window, pane->prefix_, [pane] { return pane->dockTitle(); });
    auto* shown = new ViewNotice(pane, dock);
    shown->follow(pane->viewed_, [pane](Controller& c) -> std::pair<ViewNotice::Level, QString> {
        if (c.simulated())
            return {ViewNotice::Level::None, {}};
        const QString why = c.whyNotWritable(pane->area_);
        return {ViewNotice::Level::Info,
                pane->lineReading() + ' ' +
                    (why.isEmpty() ? pane->lineWriting() : ParameterTablePane::tr("They cannot be changed now: %1.").arg(why))};
    });
    dock->setWidget(shown);
    window->addDockWidget(Qt::LeftDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the workspaces place it
    return dock;
}

} // namespace k528::studio
