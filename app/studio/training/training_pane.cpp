#include "training/training_pane.h"
#include "session/file_problem.h"

#include "training/training_texts.h"

#include "constants/constants_lock.h"

#include "window_language.h"
#include "session/core_texts.h"
#include "session/shop_database.h"
#include "training/exercise.h"
#include "training/record.h"
#include "widgets.h"
#include "workspace/pane_dock.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QDockWidget>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMainWindow>
#include <QMessageBox>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSplitter>
#include <QTableWidget>
#include <QTabWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace k528::studio {

namespace {

// An exercise's words (its title, task, hints: Russian and English in its file).
QString said(const training::Bilingual& b) { return coreText(b.ru, b.en); }

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

QString points(double p) {
    return QString::number(p, 'g', 4);
}

// The name of an attempt at a program the editor holds without a file: kept
// in the database in English (as core keeps its data), shown in the
// window's language — also for the rows a Russian window kept before.
const char* const kEditorProgram = QT_TRANSLATE_NOOP("k528::studio::TrainingPane", "the editor's program");

QString shownName(const QString& stored) {
    if (stored == QLatin1String(kEditorProgram) || stored == QStringLiteral("программа из редактора"))
        return QCoreApplication::translate("k528::studio::TrainingPane", kEditorProgram);
    return stored;
}

} // namespace

// --- PartView ------------------------------------------------------------------

PartView::PartView(QWidget* parent) : QWidget(parent) {
    setObjectName("training.part");
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void PartView::setDrawing(const training::DrawingShapes& d, std::vector<training::Shape> blank) {
    drawing_ = d;
    blank_ = std::move(blank);
    finished_.clear();
    over_.clear();
    under_.clear();
    update();
}

void PartView::setGrade(const training::Grade* g) {
    finished_.clear();
    over_.clear();
    under_.clear();
    if (g) {
        drawing_ = g->drawing;
        if (!g->blank.empty())
            blank_ = g->blank;
        finished_ = g->finished;
        for (const training::Deviation& d : g->overcut)
            over_.insert(over_.end(), d.shapes.begin(), d.shapes.end());
        for (const training::Deviation& d : g->undercut)
            under_.insert(under_.end(), d.shapes.begin(), d.shapes.end());
    }
    update();
}

void PartView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    // The extent of everything drawn, in (z, r).
    double z0 = 1e300, z1 = -1e300, r0 = 0, r1 = -1e300;
    const auto extend = [&](const std::vector<training::Shape>& shapes) {
        for (const training::Shape& s : shapes)
            for (const stock::PointZR& q : s.outer) {
                z0 = std::min(z0, q.z);
                z1 = std::max(z1, q.z);
                r0 = std::min(r0, q.r);
                r1 = std::max(r1, q.r);
            }
    };
    extend(blank_);
    extend(drawing_.most);
    extend(finished_);
    if (z1 <= z0 || r1 <= r0) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                   TrainingPane::tr("Nothing is machined in this exercise"));
        return;
    }
    const double margin = 10;
    const double sx = (width() - 2 * margin) / (z1 - z0), sy = (height() - 2 * margin) / (r1 - r0);
    const double s = std::max(1e-6, std::min(sx, sy)); // one scale: the part's true shape
    const double ox = margin + ((width() - 2 * margin) - s * (z1 - z0)) / 2;
    const double oy = height() - margin - ((height() - 2 * margin) - s * (r1 - r0)) / 2;
    const auto at = [&](const stock::PointZR& q) { return QPointF(ox + (q.z - z0) * s, oy - (q.r - r0) * s); };
    const auto path = [&](const std::vector<training::Shape>& shapes) {
        QPainterPath pp;
        pp.setFillRule(Qt::OddEvenFill);
        for (const training::Shape& sh : shapes) {
            const auto ring = [&](const stock::Ring& r) {
                if (r.empty())
                    return;
                pp.moveTo(at(r.front()));
                for (std::size_t i = 1; i < r.size(); ++i)
                    pp.lineTo(at(r[i]));
                pp.closeSubpath();
            };
            ring(sh.outer);
            for (const stock::Ring& h : sh.holes)
                ring(h);
        }
        return pp;
    };
    p.setRenderHint(QPainter::Antialiasing);
    p.fillPath(path(blank_), QColor(0xe4, 0xe4, 0xe4));
    if (!finished_.empty()) {
        p.fillPath(path(finished_), QColor(0x9f, 0xb6, 0xcd));
        p.setPen(QPen(QColor(0x33, 0x4d, 0x66), 1));
        p.drawPath(path(finished_));
    }
    // The tolerance limits thin and dashed, the nominal contour over them.
    p.setPen(QPen(QColor(0x2e, 0x8b, 0x57), 1, Qt::DashLine));
    p.drawPath(path(drawing_.most));
    p.drawPath(path(drawing_.least));
    p.setPen(QPen(Qt::black, 1.5));
    p.drawPath(path(drawing_.nominal));
    // Deviations are thin beside the part: outlined as well as filled.
    const auto mark = [&](const std::vector<training::Shape>& shapes, QColor c) {
        const QPainterPath pp = path(shapes);
        p.fillPath(pp, c);
        p.setPen(QPen(c, 3));
        p.drawPath(pp);
    };
    mark(over_, QColor(0xd0, 0x20, 0x20));
    mark(under_, QColor(0xe8, 0x9a, 0x00));
}

// --- TrainingPane ----------------------------------------------------------------

TrainingPane::TrainingPane(std::function<std::pair<QString, QString>()> editorText, QWidget* parent)
    : QWidget(parent), editorText_(std::move(editorText)) {
    setObjectName("training");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    exerciseLabel_ = new QLabel(this);
    exercise_ = namedWidget<QComboBox>(this, "training.exercise");
    exercise_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    exercise_->setMinimumContentsLength(12);
    for (const training::Exercise& e : training::shippedExercises())
        exercise_->addItem(QString(), q(e.id));
    layout->addLayout(fieldRow(exerciseLabel_, exercise_, {}));

    studentLabel_ = new QLabel(this);
    student_ = namedWidget<QLineEdit>(this, "training.student");
    gradeEditor_ = namedWidget<QPushButton>(this, "training.gradeEditor");
    gradeFile_ = namedWidget<QPushButton>(this, "training.gradeFile");
    layout->addLayout(fieldRow(studentLabel_, student_, {gradeEditor_, gradeFile_}));

    tabs_ = new QTabWidget(this);
    tabs_->setObjectName("training.tabs");
    // The task and the drawing.
    auto* taskPage = new QSplitter(Qt::Vertical, tabs_);
    taskPage->setObjectName("training.taskPage");
    task_ = new QTextBrowser(taskPage);
    task_->setObjectName("training.task");
    part_ = new PartView(taskPage);
    taskPage->addWidget(task_);
    taskPage->addWidget(part_);
    taskPage->setStretchFactor(0, 1);
    taskPage->setStretchFactor(1, 1);
    tabs_->addTab(taskPage, QString());
    // The attempt: the score, the deductions, the program graded.
    auto* attemptPage = new QWidget(tabs_);
    auto* al = new QVBoxLayout(attemptPage);
    al->setContentsMargins(0, 4, 0, 0);
    score_ = new QLabel(attemptPage);
    score_->setObjectName("training.score");
    score_->setWordWrap(true);
    al->addWidget(score_);
    auto* split = new QSplitter(Qt::Vertical, attemptPage);
    deductions_ = new QListWidget(split);
    deductions_->setObjectName("training.deductions");
    deductions_->setWordWrap(true);
    listing_ = new QPlainTextEdit(split);
    listing_->setObjectName("training.listing");
    listing_->setReadOnly(true);
    listing_->setLineWrapMode(QPlainTextEdit::NoWrap);
    split->addWidget(deductions_);
    split->addWidget(listing_);
    al->addWidget(split, 1);
    tabs_->addTab(attemptPage, QString());
    // The class: every attempt of the session.
    auto* classPage = new QWidget(tabs_);
    auto* cl = new QVBoxLayout(classPage);
    cl->setContentsMargins(0, 4, 0, 0);
    attempts_ = new QTableWidget(0, 5, classPage);
    attempts_->setObjectName("training.attempts");
    attempts_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    attempts_->setSelectionBehavior(QAbstractItemView::SelectRows);
    attempts_->verticalHeader()->hide();
    attempts_->horizontalHeader()->setStretchLastSection(true);
    classNote_ = new QLabel(classPage);
    classNote_->setObjectName("training.classNote");
    classNote_->setWordWrap(true);
    classNote_->hide();
    cl->addWidget(classNote_);
    cl->addWidget(attempts_, 1);
    // The trainer's lock of the machine constants for the class.
    auto* lockRow = new QHBoxLayout;
    lockNote_ = new QLabel(classPage);
    lockNote_->setObjectName("training.lockNote");
    lockNote_->setWordWrap(true);
    lockButton_ = new QPushButton(classPage);
    lockButton_->setObjectName("training.lock");
    lockButton_->setEnabled(false); // until the window names its machine
    lockRow->addWidget(lockButton_);
    lockRow->addWidget(lockNote_, 1);
    cl->addLayout(lockRow);
    auto* classButtons = new QHBoxLayout;
    refresh_ = new QPushButton(classPage);
    refresh_->setObjectName("training.refresh");
    csv_ = new QPushButton(classPage);
    csv_->setObjectName("training.csv");
    pdf_ = new QPushButton(classPage);
    pdf_->setObjectName("training.pdf");
    classButtons->addStretch(1);
    classButtons->addWidget(refresh_);
    classButtons->addWidget(csv_);
    classButtons->addWidget(pdf_);
    cl->addLayout(classButtons);
    tabs_->addTab(classPage, QString());
    layout->addWidget(tabs_, 1);

    connect(exercise_, &QComboBox::currentIndexChanged, this, [this] {
        last_.reset();
        showExercise();
        showGrade();
    });
    connect(gradeEditor_, &QPushButton::clicked, this, &TrainingPane::gradeEditor);
    connect(gradeFile_, &QPushButton::clicked, this, &TrainingPane::gradeFile);
    connect(csv_, &QPushButton::clicked, this, &TrainingPane::exportDialog);
    connect(pdf_, &QPushButton::clicked, this, &TrainingPane::exportPdfDialog);
    connect(lockButton_, &QPushButton::clicked, this, &TrainingPane::lockClicked);
    connect(refresh_, &QPushButton::clicked, this, &TrainingPane::reloadClass);
    // The class read when its tab is shown (other processes and PCs record too).
    connect(tabs_, &QTabWidget::currentChanged, this, [this](int i) {
        if (i == 2)
            reloadClass();
    });
    connect(deductions_, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        const int program = item->data(Qt::UserRole).toInt();
        const int line = item->data(Qt::UserRole + 1).toInt();
        if (line <= 0)
            return;
        const QTextBlock b = listing_->document()->findBlockByNumber(line - 1);
        if (b.isValid()) {
            QTextCursor c(b);
            c.select(QTextCursor::LineUnderCursor);
            listing_->setTextCursor(c);
            listing_->centerCursor();
        }
        emit lineActivated(program, line);
    });
    connect(deductions_, &QListWidget::itemClicked, deductions_, &QListWidget::itemActivated);
    retranslate();
}

TrainingPane::~TrainingPane() {
    if (watcher_)
        static_cast<QFutureWatcher<training::Grade>*>(watcher_)->waitForFinished();
}

const training::Exercise* TrainingPane::current() const {
    return training::findExercise(exercise_->currentData().toString().toStdString());
}

bool TrainingPane::selectExercise(const QString& id) {
    const int i = exercise_->findData(id);
    if (i < 0)
        return false;
    exercise_->setCurrentIndex(i);
    return true;
}

void TrainingPane::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void TrainingPane::retranslate() {
    const auto& all = training::shippedExercises();
    for (int i = 0; i < exercise_->count() && i < static_cast<int>(all.size()); ++i)
        exercise_->setItemText(i, QStringLiteral("%1. %2").arg(i + 1).arg(said(all[static_cast<std::size_t>(i)].title)));
    exerciseLabel_->setText(tr("Exercise:"));
    studentLabel_->setText(tr("Student:"));
    student_->setPlaceholderText(tr("the student's name"));
    gradeEditor_->setText(tr("Grade the editor's program"));
    gradeEditor_->setToolTip(tr("Runs the editor's program on a simulated machine of its own as the operator "
                                "would and grades the part"));
    gradeFile_->setText(tr("Grade a file…"));
    csv_->setText(tr("Export CSV"));
    pdf_->setText(tr("Export PDF"));
    pdf_->setToolTip(tr("The class report as PDF: each attempt with its score and deductions"));
    tabs_->setTabText(0, tr("Task"));
    tabs_->setTabText(1, tr("Attempt"));
    tabs_->setTabText(2, tr("Class"));
    showLock();
    refresh_->setText(tr("Refresh"));
    refresh_->setToolTip(tr("Reads the class's attempts from the database again"));
    attempts_->setHorizontalHeaderLabels({tr("Student"), tr("Exercise"), tr("Score"), tr("Result"), tr("Time")});
    showClass();
    showExercise();
    showGrade();
}

void TrainingPane::showExercise() {
    const training::Exercise* e = current();
    if (!e) {
        task_->clear();
        part_->setDrawing({}, {});
        return;
    }
    const auto para = [](const training::Bilingual& b) {
        return QStringLiteral("<p>") + said(b).toHtmlEscaped().replace(QLatin1Char('\n'), QLatin1Char(' ')) +
               QStringLiteral("</p>");
    };
    QString html = QStringLiteral("<h3>") + said(e->title).toHtmlEscaped() + QStringLiteral("</h3>");
    html += para(e->task);
    QStringList facts;
    if (e->limits.cycleTimeS > 0)
        facts << tr("Cycle time at most %1 s").arg(e->limits.cycleTimeS);
    if (e->drawing.kind == training::Drawing::Kind::Contour)
        facts << tr("The drawing: the half profile below, black; its tolerance limits dashed");
    else if (e->drawing.kind == training::Drawing::Kind::Bore)
        facts << tr("The drawing: bore Ø%1, %2/%3 mm")
                     .arg(e->drawing.boreMm)
                     .arg(e->drawing.boreTol.upperMm, 0, 'g', 4)
                     .arg(e->drawing.boreTol.lowerMm, 0, 'g', 4);
    else if (e->drawing.kind == training::Drawing::Kind::Reference)
        facts << tr("The drawing: the part the reference program makes, ±%1 mm").arg(e->drawing.tolerance.upperMm);
    for (const QString& f : facts)
        html += QStringLiteral("<p><i>") + f.toHtmlEscaped() + QStringLiteral("</i></p>");
    for (const training::Bilingual& h : e->hints)
        html += QStringLiteral("<p>") + tr("Hint:").toHtmlEscaped() + QLatin1Char(' ') +
                said(h).toHtmlEscaped() + QStringLiteral("</p>");
    task_->setHtml(html);
    if (!last_ || last_->grade.exercise != e->id) {
        std::vector<training::Shape> blank;
        if (e->lathe()) {
            const stock::Stock s(*e->blank);
            for (std::size_t i = 0; i < s.polygons(); ++i) {
                training::Shape sh;
                for (const stock::PointZR& p : s.outer(i))
                    sh.outer.push_back({p.z + e->blankZMm, p.r});
                blank.push_back(std::move(sh));
            }
        }
        training::DrawingShapes d;
        if (e->drawing.kind == training::Drawing::Kind::Contour || e->drawing.kind == training::Drawing::Kind::Bore)
            d = training::drawingShapes(*e);
        part_->setDrawing(d, std::move(blank));
    }
}

void TrainingPane::showGrade() {
    deductions_->clear();
    if (!last_ || !current() || last_->grade.exercise != current()->id) {
        score_->setText(status_.isEmpty() ? tr("No attempt graded yet: write the program in the editor, "
                                               "then «Grade the editor's program»")
                                          : status_);
        listing_->clear();
        part_->setGrade(nullptr);
        return;
    }
    const training::Grade& g = last_->grade;
    QString who = shownName(last_->student.isEmpty() ? last_->file : last_->student);
    QString text = tr("%1: %2/100, %3").arg(who).arg(g.score).arg(g.passed ? tr("passed") : tr("not passed"));
    if (g.cycleTimeS > 0)
        text += QStringLiteral("; ") + tr("cycle time %1 s").arg(g.cycleTimeS, 0, 'f', 1);
    if (g.limitS > 0)
        text += QStringLiteral(" ") + tr("(limit %1 s)").arg(g.limitS);
    if (last_->recordedId == 0 && !recordError_.isEmpty())
        text += QStringLiteral("\n") + tr("Not kept in the database: %1").arg(recordError_);
    score_->setText(text);
    for (const training::Deduction& d : g.deductions) {
        auto* item = new QListWidgetItem(QStringLiteral("−%1  %2").arg(points(d.points), trainingText(d.text)),
                                         deductions_);
        item->setData(Qt::UserRole, d.program);
        item->setData(Qt::UserRole + 1, d.line);
        if (d.fails)
            item->setForeground(QColor(0xb0, 0x10, 0x10));
    }
    for (const training::StepNote& n : g.notes)
        new QListWidgetItem(tr("line %1 «%2»: %3").arg(n.line).arg(q(n.token), trainingText(n.text)), deductions_);
    if (g.deductions.empty())
        new QListWidgetItem(tr("No deductions"), deductions_);
    part_->setGrade(&g);
}

void TrainingPane::gradeEditor() {
    const auto [text, name] = editorText_ ? editorText_() : std::pair<QString, QString>();
    if (text.trimmed().isEmpty()) {
        status_ = tr("The editor holds no program: open the student's file in the editor or use «Grade a file…»");
        last_.reset();
        showGrade();
        tabs_->setCurrentIndex(1);
        return;
    }
    grade(text, name.isEmpty() ? QString::fromLatin1(kEditorProgram) : name);
}

void TrainingPane::gradeFile() {
    const QString path = QFileDialog::getOpenFileName(this, tr("The student's program"), QString(),
                                                      tr("K528 programs (*.k528 *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    std::string text;
    QString error;
    if (!readTextFile(path, text, error)) { // why in the window's language
        QMessageBox::warning(this, tr("Training"), error);
        return;
    }
    if (student_->text().trimmed().isEmpty())
        student_->setText(QFileInfo(path).completeBaseName());
    grade(QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())), QFileInfo(path).fileName());
}

bool TrainingPane::grade(const QString& text, const QString& file) {
    const training::Exercise* e = current();
    if (!e || watcher_)
        return false;
    Attempt a;
    a.student = student_->text().trimmed();
    a.exercise = q(e->id);
    a.file = file;
    a.program = text.toStdString();
    auto* watcher = new QFutureWatcher<training::Grade>(this);
    watcher_ = watcher;
    gradeEditor_->setEnabled(false);
    gradeFile_->setEnabled(false);
    status_ = tr("Grading: the program runs on the simulated machine…");
    last_.reset();
    showGrade();
    tabs_->setCurrentIndex(1);
    listing_->setPlainText(text);
    connect(watcher, &QFutureWatcher<training::Grade>::finished, this, [this, watcher, a]() mutable {
        watcher_ = nullptr;
        watcher->deleteLater();
        gradeEditor_->setEnabled(true);
        gradeFile_->setEnabled(true);
        try {
            a.grade = watcher->result();
        } catch (const std::exception& err) {
            status_ = tr("The attempt could not be graded: %1").arg(coreErrorText(err));
            showGrade();
            return;
        }
        a.when = QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
        status_.clear();
        record(a);
        last_ = a;
        attemptList_.push_back(a);
        reloadClass();
        showGrade();
        emit graded(a.grade.score, a.grade.passed);
    });
    // Each attempt its own simulated machine and grader (grading is
    // deterministic and touches nothing of the session's).
    const std::string programText = text.toStdString(), fileName = file.toStdString(),
                      student = a.student.toStdString();
    watcher->setFuture(QtConcurrent::run([e, programText, fileName, student] {
        const training::Grader grader(*e);
        return grader.grade(programText, fileName, student);
    }));
    return true;
}

void TrainingPane::record(Attempt& a) {
    recordError_.clear();
    db::AttemptEntry entry = training::attemptEntry(a.grade, a.program);
    if (!a.student.isEmpty())
        entry.student = a.student.toStdString();
    try {
        a.recordedId = ShopDatabase::at()->use([&](db::Database& d) { return d.recordAttempt(entry).id; });
    } catch (const std::exception& e) {
        a.recordedId = 0;
        recordError_ = databaseErrorText(e);
    }
}

void TrainingPane::reloadClass() {
    classRows_.clear();
    classError_.clear();
    // This session's attempts the database did not take, newest first.
    for (auto it = attemptList_.rbegin(); it != attemptList_.rend(); ++it)
        if (it->recordedId == 0) {
            db::AttemptEntry e = training::attemptEntry(it->grade, it->program);
            if (!it->student.isEmpty())
                e.student = it->student.toStdString();
            e.at = QDateTime::fromString(it->when, QStringLiteral("yyyy-MM-dd HH:mm:ss"))
                       .toUTC()
                       .toString(Qt::ISODate)
                       .toStdString();
            classRows_.push_back(std::move(e));
        }
    try {
        db::AttemptFilter f;
        f.limit = 1000;
        const auto stored = ShopDatabase::at()->use([&](db::Database& d) { return d.attempts(f); });
        classRows_.insert(classRows_.end(), stored.begin(), stored.end());
    } catch (const std::exception& e) {
        classError_ = databaseErrorText(e);
    }
    showClass();
}

void TrainingPane::showClass() {
    if (classError_.isEmpty()) {
        classNote_->hide();
    } else {
        classNote_->setText(tr("The database cannot be read: only this session's attempts are listed (%1)")
                                .arg(classError_));
        classNote_->show();
    }
    attempts_->setRowCount(0);
    for (const db::AttemptEntry& a : classRows_) {
        const int r = attempts_->rowCount();
        attempts_->insertRow(r);
        const QDateTime at = QDateTime::fromString(q(a.at), Qt::ISODate);
        // The exercise by its title in the window's language (its id if the course has it no more).
        const training::Exercise* ex = training::findExercise(a.exercise);
        const QString exercise =
            ex ? said(ex->title) : q(a.exercise);
        const QStringList cells{shownName(q(a.student)), exercise, QString::number(a.score),
                                a.passed ? tr("passed") : tr("not passed"),
                                at.isValid() ? at.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : q(a.at)};
        for (int c = 0; c < cells.size(); ++c)
            attempts_->setItem(r, c, new QTableWidgetItem(cells[c]));
    }
}

QString TrainingPane::exportCsv(const QString& path) const {
    const auto field = [](QString s) {
        if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')) || s.contains(QLatin1Char('\n')))
            s = QLatin1Char('"') + s.replace(QLatin1String("\""), QLatin1String("\"\"")) + QLatin1Char('"');
        return s;
    };
    QString out = QStringLiteral("student,exercise,file,time,score,passed,status,cycle_time_s,deductions\n");
    for (const db::AttemptEntry& a : classRows_) {
        QStringList ded;
        for (const training::Deduction& d : training::storedDeductions(a))
            ded << QStringLiteral("-%1 %2").arg(points(d.points), trainingText(d.text));
        out += QStringList{field(q(a.student)), field(q(a.exercise)), field(q(a.file)), field(q(a.at)),
                           QString::number(a.score), a.passed ? QStringLiteral("yes") : QStringLiteral("no"),
                           field(q(a.status)), QString::number(static_cast<double>(a.cycleTimeMs) / 1000.0, 'f', 3),
                           field(ded.join(QStringLiteral("; ")))}
                   .join(QLatin1Char(',')) +
               QLatin1Char('\n');
    }
    SaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return fileProblem(f);
    f.write(out.toUtf8());
    if (!f.commit())
        return fileProblem(f);
    return {};
}

void TrainingPane::exportDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export CSV"), QStringLiteral("attempts.csv"),
                                                      tr("CSV (*.csv)"));
    if (path.isEmpty())
        return;
    const QString error = exportCsv(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export CSV"), tr("Cannot write %1: %2").arg(path, error));
}

QString TrainingPane::exportPdf(const QString& path) const {
    const auto esc = [](const QString& s) { return s.toHtmlEscaped(); };
    QString html = QStringLiteral("<html><body style=\"font-family: 'DejaVu Sans', sans-serif;\">");
    html += QStringLiteral("<h2>") + esc(tr("Training course: class report")) + QStringLiteral("</h2>");
    html += QStringLiteral("<p>") +
            esc(tr("Attempts: %1; printed %2")
                    .arg(classRows_.size())
                    .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")))) +
            QStringLiteral("</p>");
    html += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">");
    html += QStringLiteral("<thead><tr>");
    for (const QString& h : {tr("Student"), tr("Exercise"), tr("File"), tr("Time"), tr("Score"), tr("Result"),
                             tr("Cycle time, s"), tr("Deductions")})
        html += QStringLiteral("<th align=\"left\">") + esc(h) + QStringLiteral("</th>");
    html += QStringLiteral("</tr></thead>");
    for (const db::AttemptEntry& a : classRows_) {
        const training::Exercise* ex = training::findExercise(a.exercise);
        const QString exercise =
            ex ? said(ex->title) : q(a.exercise);
        const QDateTime at = QDateTime::fromString(q(a.at), Qt::ISODate);
        QStringList ded;
        for (const training::Deduction& d : training::storedDeductions(a))
            ded << esc(QStringLiteral("−%1 %2").arg(points(d.points), trainingText(d.text)));
        const QStringList cells{esc(shownName(q(a.student))),
                                esc(exercise),
                                esc(shownName(q(a.file))),
                                esc(at.isValid() ? at.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))
                                                 : q(a.at)),
                                QString::number(a.score),
                                esc(a.passed ? tr("passed") : tr("not passed")),
                                QString::number(static_cast<double>(a.cycleTimeMs) / 1000.0, 'f', 1),
                                ded.join(QStringLiteral("<br>"))};
        html += QStringLiteral("<tr>");
        for (const QString& c : cells)
            html += QStringLiteral("<td valign=\"top\">") + c + QStringLiteral("</td>");
        html += QStringLiteral("</tr>");
    }
    html += QStringLiteral("</table></body></html>");
    SaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return fileProblem(f);
    {
        QPdfWriter writer(&f);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageOrientation(QPageLayout::Landscape);
        writer.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
        writer.setResolution(300);
        writer.setTitle(tr("Training course: class report"));
        writer.setCreator(QStringLiteral("K528 Studio"));
        QTextDocument doc;
        QFont font(QStringLiteral("DejaVu Sans"));
        font.setPointSizeF(8);
        doc.setDefaultFont(font);
        doc.setHtml(html);
        doc.print(&writer);
    }
    if (!f.commit())
        return fileProblem(f);
    return {};
}

void TrainingPane::exportPdfDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export PDF"), QStringLiteral("class-report.pdf"),
                                                      tr("PDF (*.pdf)"));
    if (path.isEmpty())
        return;
    const QString error = exportPdf(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export PDF"), tr("Cannot write %1: %2").arg(path, error));
}

void TrainingPane::setMachine(const profile::MachineProfile& machine) {
    if (lock_)
        disconnect(lock_, nullptr, this, nullptr);
    lock_ = ConstantsLock::of(machine);
    connect(lock_, &ConstantsLock::changed, this, &TrainingPane::showLock);
    lock_->refresh();
    showLock();
}

void TrainingPane::showLock() {
    lockButton_->setEnabled(lock_ != nullptr);
    if (!lock_) {
        lockButton_->setText(tr("Lock the constants…"));
        lockNote_->clear();
        return;
    }
    if (lock_->locked()) {
        lockButton_->setText(tr("Unlock the constants"));
        lockButton_->setToolTip(tr("Lets the machine constants be changed again"));
        lockNote_->setText(tr("The machine constants are locked for the class «%1»").arg(lock_->holder()));
    } else {
        lockButton_->setText(tr("Lock the constants…"));
        lockButton_->setToolTip(tr("Locks the machine constants for a class: the constants dock and the "
                                   "K923 refuse changes until you unlock them (kept in the database)"));
        lockNote_->setText(tr("The machine constants may be changed"));
    }
}

QString TrainingPane::lockConstants(const QString& forClass) {
    if (!lock_)
        return tr("No machine");
    return lock_->lock(forClass);
}

QString TrainingPane::unlockConstants() {
    if (!lock_)
        return tr("No machine");
    return lock_->unlock();
}

void TrainingPane::lockClicked() {
    if (!lock_)
        return;
    lock_->refresh(); // another PC may have done it meanwhile
    QString error;
    if (lock_->locked()) {
        error = unlockConstants();
    } else {
        bool ok = false;
        const QString cls = QInputDialog::getText(this, tr("Lock the machine constants"),
                                                  tr("The class the constants are locked for:"), QLineEdit::Normal,
                                                  QString(), &ok);
        if (!ok || cls.trimmed().isEmpty())
            return;
        error = lockConstants(cls);
    }
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Lock the machine constants"), error);
    showLock();
}

// --- the dock ------------------------------------------------------------------------

QDockWidget* addTrainingDock(QMainWindow* window, std::function<std::pair<QString, QString>()> editorText) {
    auto* dock = new PaneDock(window, "training", [] { return TrainingPane::tr("Training course"); });
    dock->setWidget(new TrainingPane(std::move(editorText), dock));
    window->addDockWidget(Qt::RightDockWidgetArea, dock);
    dock->hide(); // shown from the View menu; the Training workspace places it
    return dock;
}

} // namespace k528::studio
