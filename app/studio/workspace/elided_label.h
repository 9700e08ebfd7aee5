// A one-line label that never widens its window: its text is drawn elided
// («L1: выполняется, кадр N15 — «ЧИСТОВ…») when the space is short, and the
// whole text is its tooltip then. Its minimum width is a few characters,
// whatever the text; its size hint is still the whole text, so it gets the
// room when there is some. Plain text only.
#pragma once

#include <QLabel>

namespace k528::studio {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget* parent = nullptr, Qt::TextElideMode mode = Qt::ElideRight);

    // Whether the text is cut where it is drawn now.
    bool isElided() const;
    // The text as drawn (elided to the label's width).
    QString shownText() const;

    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;

private:
    Qt::TextElideMode mode_;
};

} // namespace k528::studio
