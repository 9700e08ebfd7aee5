#include "backplot/backplot_dock.h"
#include "workspace/flow_layout.h"

#include "backplot/backplot_widget.h"
#include "engine/rparams.h"
#include "session/simulation_session.h"
#include "toolpath/actual_path.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace k528::studio::backplot {

namespace {

class BackplotDock final : public QDockWidget {
    Q_OBJECT
public:
    BackplotDock(QMainWindow* w, SimulationSession& session) : QDockWidget(w), session_(session) {
        setObjectName("dock.backplot");
        auto* box = new QWidget(this);
        auto* row = new FlowLayout; // wraps in a narrow dock
        programLabel_ = new QLabel(box);
        program_ = new QSpinBox(box);
        program_->setObjectName("backplot.program");
        program_->setRange(1, 99);
        program_->setPrefix("L");
        pathButton_ = new QPushButton(box);
        pathButton_->setObjectName("backplot.computePath");
        runButton_ = new QPushButton(box);
        runButton_->setObjectName("backplot.simulateRun");
        ucgLabel_ = new QLabel(box);
        ucg_ = new QLineEdit(box);
        ucg_->setObjectName("backplot.ucg");
        ucg_->setText(QStringLiteral("UCG,2,Z-100Z0,X50X0,S0S0,0,-5"));
        follow_ = new QCheckBox(box);
        follow_->setObjectName("backplot.followMachine");
        follow_->setChecked(true);
        row->addGroup({programLabel_, program_});
        row->addWidget(pathButton_);
        row->addWidget(runButton_);
        // The blank on a row of its own: one long row made the dock (and the
        // window) wider than a 1920-pixel screen.
        auto* stockRow = new QHBoxLayout;
        stockRow->addWidget(follow_);
        stockRow->addWidget(ucgLabel_);
        stockRow->addWidget(ucg_, 1);
        view_ = new BackplotWidget(box);
        auto* layout = new QVBoxLayout(box);
        layout->setContentsMargins(2, 2, 2, 2);
        layout->addLayout(row);
        layout->addLayout(stockRow);
        layout->addWidget(view_, 1);
        setWidget(box);
        connect(pathButton_, &QPushButton::clicked, this, [this] { computePath(); });
        connect(runButton_, &QPushButton::clicked, this, [this] {
            view_->showActualRun(session_.simulation().profile(), session_.controller().programs(),
                                 program_->value());
        });
        // The path of a run on the session's machine grows live: every tick
        // is sampled (a copy), each UI frame (advanced()) draws the batch.
        live_.attach(session_.simulation());
        connect(&session_, &QObject::destroyed, this, [this] { live_.abandon(); });
        connect(&session_, &SimulationSession::advanced, this, [this] { liveFrame(); });
        retranslate();
        const program::ProgramStore& store = session_.controller().programs();
        if (!store.programs().empty()) {
            program_->setValue(store.programs().front().number);
            computePath();
        }
    }

protected:
    void changeEvent(QEvent* e) override {
        if (e->type() == QEvent::LanguageChange)
            retranslate();
        QDockWidget::changeEvent(e);
    }

private:
    void liveFrame() {
        const toolpath::LiveActualPath::Batch b = live_.flush();
        if (!follow_->isChecked() || (b.raw == 0 && !b.restarted && !liveShown_))
            return;
        if (b.restarted) {
            // The running program's programmed path under it (АВТОМАТ's choice, R252).
            const program::ProgramStore& store = session_.controller().programs();
            int number = session_.controller().r(engine::r::SelectedProgram);
            if (!store.contains(number))
                number = live_.program();
            if (store.contains(number) && (number != view_->scene().path().program ||
                                           session_.controller().programsRevision() != pathRevision_)) {
                program_->setValue(number);
                computePath();
            }
        }
        std::optional<k528::backplot::BackplotScene::LiveTool> tool;
        const toolpath::ActualPath& path = live_.path();
        if (live_.running() && !path.samples.empty()) {
            const toolpath::ActualSample& s = path.samples.back();
            const engine::Controller& c = session_.controller();
            const units::AxisScale sx = c.axisView(engine::AxisId::X).scale;
            tool = k528::backplot::BackplotScene::LiveTool{
                s.z, s.x, units::discToMm(c.r(engine::r::WheelCurrent), sx)};
        }
        view_->appendLive(path, b.restarted ? 0 : b.firstNew, tool);
        liveShown_ = live_.running();
    }
    void computePath() {
        const program::ProgramStore& store = session_.controller().programs();
        if (!store.contains(program_->value()))
            return;
        pathRevision_ = session_.controller().programsRevision();
        view_->showProgram(session_.simulation().profile(), store, program_->value(),
                           stock::parseUcg(ucg_->text().toStdString()));
    }
    void retranslate() {
        setWindowTitle(tr("Backplot"));
        programLabel_->setText(tr("Program"));
        pathButton_->setText(tr("Programmed path"));
        runButton_->setText(tr("Simulate run"));
        runButton_->setToolTip(tr("Run the program on the simulated machine and overlay the "
                                  "actual path, coloured by following error"));
        ucgLabel_->setText(tr("Blank (UCG)"));
        follow_->setText(tr("Follow the machine"));
        follow_->setToolTip(tr("While the session's machine runs a program, its path grows here live"));
    }

    SimulationSession& session_;
    QLabel *programLabel_ = nullptr, *ucgLabel_ = nullptr;
    QSpinBox* program_ = nullptr;
    QPushButton *pathButton_ = nullptr, *runButton_ = nullptr;
    QLineEdit* ucg_ = nullptr;
    QCheckBox* follow_ = nullptr;
    BackplotWidget* view_ = nullptr;
    toolpath::LiveActualPath live_;
    bool liveShown_ = false;
    std::uint64_t pathRevision_ = ~std::uint64_t{0}; // of the store the path was computed from
};

} // namespace

QDockWidget* addBackplotDock(QMainWindow* window, SimulationSession& session) {
    QDockWidget* dock = nullptr;
    if (QGuiApplication::platformName() == QLatin1String("offscreen")) {
        // QOpenGLWidget crashes on the offscreen platform (widget tests):
        // the dock says so instead (platform.md).
        dock = new QDockWidget(window);
        dock->setObjectName("dock.backplot");
        dock->setWindowTitle(BackplotDock::tr("Backplot"));
        auto* label = new QLabel(BackplotDock::tr("The backplot needs OpenGL (an X display)"), dock);
        label->setAlignment(Qt::AlignCenter);
        label->setWordWrap(true);
        dock->setWidget(label);
    } else {
        dock = new BackplotDock(window, session);
    }
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                      QDockWidget::DockWidgetClosable);
    window->addDockWidget(Qt::LeftDockWidgetArea, dock);
    return dock;
}

} // namespace k528::studio::backplot

#include "backplot_dock.moc"
