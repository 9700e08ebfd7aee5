#include "backplot/backplot_dock.h"
#include "workspace/flow_layout.h"
#include "workspace/pane_dock.h"

#include "backplot/backplot_widget.h"
#include "controller/controller.h"
#include "controller/simulated_machine.h"
#include "controller/view_notice.h"
#include "engine/rparams.h"
#include "machine/simulation.h"
#include "toolpath/actual_path.h"

#include <QCheckBox>
#include <QElapsedTimer>
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
#include <algorithm>
#include <memory>

namespace k528::studio::backplot {

namespace {

class BackplotDock final : public PaneDock {
    Q_OBJECT
public:
    BackplotDock(QMainWindow* w, ViewedController& viewed) : PaneDock(w, "backplot"), viewed_(viewed) {
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
        auto* notice = new ViewNotice(box, this);
        notice->setObjectName("backplot.notice");
        notice->follow(viewed, [this](Controller& c) -> std::pair<ViewNotice::Level, QString> {
            if (c.simulated())
                return {ViewNotice::Level::None, {}};
            if (!waitingFor_.isEmpty())
                return {ViewNotice::Level::Info, waitingFor_};
            return {ViewNotice::Level::Info,
                    tr("The actual path grows from the controller's live positions, read %1 times a second; a "
                       "program's path once its text is read from the controller.")
                        .arg(c.capabilities().liveRateHz, 0, 'f', 0)};
        });
        notice_ = notice;
        setWidget(notice);
        connect(pathButton_, &QPushButton::clicked, this, [this] { computePath(); });
        connect(runButton_, &QPushButton::clicked, this, [this] {
            view_->showActualRun(controller().profile(), controller().programs(), program_->value());
        });
        connect(&viewed, &ViewedController::changed, this, [this] { follow(); });
        follow();
        retranslate();
    }

private:
    Controller& controller() const { return viewed_.current(); }

    // The controller shown: a simulated machine's every tick is sampled (a
    // copy) and each UI frame draws the batch; a real controller's live
    // positions are sampled at each poll.
    void follow() {
        live_->detach();
        live_ = std::make_unique<toolpath::LiveActualPath>();
        disconnect(updates_);
        Controller& c = controller();
        if (SimulatedMachine* sim = c.simulated()) {
            live_->attach(sim->simulation());
            connect(sim->lifetime(), &QObject::destroyed, this, [this] { live_->abandon(); });
            updates_ = connect(&c, &Controller::updated, this, [this] {
                liveFrame();
                pathArrived();
            });
        } else {
            clock_.start();
            updates_ = connect(&c, &Controller::updated, this, [this] {
                const ControllerState& st = controller().state();
                if (st.connected) {
                    toolpath::ActualSample s;
                    const bool active = toolpath::sampleOfViews(st.program, st.axes, static_cast<double>(clock_.elapsed()), s);
                    live_->observe(active ? &s : nullptr);
                }
                liveFrame();
                pathArrived();
            });
        }
        pathRevision_ = ~std::uint64_t{0};
        waitingFor_.clear();
        const program::ProgramStore& store = c.programs();
        if (!store.programs().empty()) {
            program_->setValue(store.programs().front().number);
            computePath();
        }
    }
    // A program asked of the controller came: its path now.
    void pathArrived() {
        if (waitingFor_.isEmpty() || !controller().programs().contains(program_->value()))
            return;
        waitingFor_.clear();
        computePath();
        notice_->refresh();
    }
    void liveFrame() {
        const toolpath::LiveActualPath::Batch b = live_->flush();
        if (!follow_->isChecked() || (b.raw == 0 && !b.restarted && !liveShown_))
            return;
        if (b.restarted) {
            // The running program's programmed path under it (АВТОМАТ's choice, R252).
            const program::ProgramStore& store = controller().programs();
            int number = controller().state().program.selectedProgram;
            if (!store.contains(number))
                number = live_->program();
            if (!store.contains(number) && number > 0) {
                program_->setValue(number);
                computePath(); // asks a real controller for its text
            } else if (store.contains(number) && (number != view_->scene().path().program ||
                                                  controller().programsRevision() != pathRevision_)) {
                program_->setValue(number);
                computePath();
            }
        }
        std::optional<k528::backplot::BackplotScene::LiveTool> tool;
        const toolpath::ActualPath& path = live_->path();
        if (live_->running() && !path.samples.empty()) {
            const toolpath::ActualSample& s = path.samples.back();
            const Controller& c = controller();
            const units::AxisScale sx = c.state().axes[0].scale;
            const auto r = c.rValues();
            const std::int64_t wheel = r.size() > engine::r::WheelCurrent ? r[engine::r::WheelCurrent] : 0;
            tool = k528::backplot::BackplotScene::LiveTool{s.z, s.x, units::discToMm(wheel, sx)};
            // The simulated turret's station (a controller on the line does not tell it).
            if (SimulatedMachine* sim = controller().simulated(); sim && sim->simulation().equipment().turret)
                tool->station = sim->simulation().equipment().turret->station();
        }
        view_->appendLive(path, b.restarted ? 0 : b.firstNew, tool);
        liveShown_ = live_->running();
    }
    void computePath() {
        Controller& c = controller();
        const program::ProgramStore& store = c.programs();
        const int number = program_->value();
        if (!store.contains(number)) {
            const auto& present = c.state().programNumbers;
            if (!c.simulated() && std::find(present.begin(), present.end(), number) != present.end()) {
                waitingFor_ = tr("Reading L%1 from the controller for its path...").arg(number);
                c.fetchProgram(number);
            } else {
                waitingFor_.clear();
            }
            notice_->refresh();
            return;
        }
        pathRevision_ = c.programsRevision();
        view_->showProgram(c.profile(), store, number, stock::parseUcg(ucg_->text().toStdString()));
    }
    void retranslate() override {
        setWindowTitle(tr("Backplot"));
        programLabel_->setText(tr("Program"));
        pathButton_->setText(tr("Programmed path"));
        runButton_->setText(tr("Simulate run"));
        runButton_->setToolTip(tr("Run the program on the simulated machine and overlay the "
                                  "actual path, coloured by following error"));
        ucgLabel_->setText(tr("Blank (UCG)"));
        follow_->setText(tr("Follow the machine"));
        follow_->setToolTip(tr("While the controller shown runs a program, its path grows here live"));
    }

    ViewedController& viewed_;
    ViewNotice* notice_ = nullptr;
    QMetaObject::Connection updates_;
    QElapsedTimer clock_;
    QString waitingFor_;
    QLabel *programLabel_ = nullptr, *ucgLabel_ = nullptr;
    QSpinBox* program_ = nullptr;
    QPushButton *pathButton_ = nullptr, *runButton_ = nullptr;
    QLineEdit* ucg_ = nullptr;
    QCheckBox* follow_ = nullptr;
    BackplotWidget* view_ = nullptr;
    std::unique_ptr<toolpath::LiveActualPath> live_ = std::make_unique<toolpath::LiveActualPath>();
    bool liveShown_ = false;
    std::uint64_t pathRevision_ = ~std::uint64_t{0}; // of the store the path was computed from
};

} // namespace

QDockWidget* addBackplotDock(QMainWindow* window, ViewedController& viewed) {
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
        dock = new BackplotDock(window, viewed);
    }
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                      QDockWidget::DockWidgetClosable);
    window->addDockWidget(Qt::LeftDockWidgetArea, dock);
    return dock;
}

} // namespace k528::studio::backplot

#include "backplot_dock.moc"
