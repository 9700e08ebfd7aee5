#include "controller/view_notice.h"
#include "workspace/screen_fit.h"

#include "controller/controller.h"

#include <QEvent>
#include <QPainter>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace k528::studio {

// A translucent veil over a greyed content, following its size.
class ViewNotice::Veil : public QWidget {
public:
    explicit Veil(QWidget* over) : QWidget(over) {
        setObjectName(QStringLiteral("viewNotice.veil"));
        setAttribute(Qt::WA_TransparentForMouseEvents);
        over->installEventFilter(this);
        setGeometry(over->rect());
        raise();
    }

protected:
    bool eventFilter(QObject* o, QEvent* e) override {
        if (o == parent() && (e->type() == QEvent::Resize || e->type() == QEvent::ChildAdded)) {
            setGeometry(parentWidget()->rect());
            raise();
        }
        return QWidget::eventFilter(o, e);
    }
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        QColor c = palette().color(QPalette::Window);
        c.setAlpha(170);
        p.fillRect(rect(), c);
    }
};

ViewNotice::ViewNotice(QWidget* content, QWidget* parent) : QWidget(parent), content_(content) {
    setObjectName(content->objectName() + QStringLiteral(".notice"));
    // Its own background under a faded content (else what was drawn there
    // before shows through).
    setAutoFillBackground(true);
    label_ = new QLabel(this);
    label_->setObjectName(QStringLiteral("viewNotice"));
    label_->setWordWrap(true);
    label_->setTextFormat(Qt::PlainText);
    label_->setMargin(4);
    label_->hide();
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(0, 0, 0, 0);
    lay->setSpacing(0);
    lay->addWidget(label_);
    lay->addWidget(content_, 1);
}

QString ViewNotice::text() const { return label_->isHidden() ? QString() : label_->text(); }

void ViewNotice::setNotice(Level level, const QString& text) {
    if (level == Level::None || text.isEmpty())
        level = Level::None;
    const bool same = level == level_ && (level == Level::None || label_->text() == text);
    level_ = level;
    content_->setEnabled(level != Level::Unavailable);
    // Greyed for the eye too (the panels paint themselves, disabled or not):
    // a veil over the content.
    QWidget* shown = scroll_ ? static_cast<QWidget*>(scroll_) : content_;
    if (level == Level::Unavailable && !veil_) {
        veil_ = new Veil(shown);
        veil_->show();
    } else if (level != Level::Unavailable && veil_) {
        delete veil_;
        veil_ = nullptr;
    }
    if (same)
        return;
    if (level == Level::None) {
        label_->hide();
        label_->clear();
        return;
    }
    label_->setText(text);
    label_->setStyleSheet(level == Level::Info    ? QStringLiteral("background:#e8eef6; color:#1d3557;")
                          : level == Level::Stale ? QStringLiteral("background:#fff1c2; color:#5c4300;")
                                                  : QStringLiteral("background:#eceff1; color:#37474f;"));
    label_->show();
}

void ViewNotice::setNotice(const Controller& c, Level level, const QString& text) {
    if (c.stale())
        setNotice(level == Level::Unavailable ? level : Level::Stale,
                  level == Level::Unavailable ? text : staleText(c));
    else
        setNotice(level, text);
}

void ViewNotice::follow(ViewedController& viewed, Say what) {
    viewed_ = &viewed;
    say_ = std::move(what);
    const auto attach = [this] {
        disconnect(updates_);
        updates_ = connect(&viewed_->current(), &Controller::updated, this, &ViewNotice::refresh);
        refresh();
    };
    connect(&viewed, &ViewedController::changed, this, attach);
    attach();
}

void ViewNotice::scrollContent() {
    if (scroll_ || qobject_cast<QAbstractScrollArea*>(content_))
        return;
    auto* lay = static_cast<QVBoxLayout*>(layout());
    scroll_ = new QScrollArea(this);
    scroll_->setObjectName(objectName() + QStringLiteral(".scroll"));
    scroll_->setFrameShape(QFrame::NoFrame);
    scroll_->setWidgetResizable(true);
    lay->removeWidget(content_);
    QWidget* kept = takeKeptInView(content_, this); // its status line stays in view below
    scroll_->setWidget(content_);
    lay->addWidget(scroll_, 1);
    if (kept)
        lay->addWidget(kept);
}

void ViewNotice::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        refresh();
    QWidget::changeEvent(e);
}

void ViewNotice::refresh() {
    if (!viewed_ || !say_)
        return;
    Controller& c = viewed_->current();
    const auto [level, text] = say_(c);
    setNotice(c, level, text);
}

} // namespace k528::studio
