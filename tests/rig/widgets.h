// What the tests of the studio's windows measure of a widget on the screen.
#pragma once

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPixmap>
#include <QPoint>
#include <QRect>
#include <QSet>
#include <QString>
#include <QWidget>

namespace k528::testrig {

// The part of `w` its parents let show, in global coordinates (empty:
// hidden behind a tab, scrolled out of its pane).
inline QRect shownRect(const QWidget* w) {
    QRect r(w->mapToGlobal(QPoint(0, 0)), w->size());
    for (const QWidget* p = w->parentWidget(); p; p = p->parentWidget()) {
        r &= QRect(p->mapToGlobal(QPoint(0, 0)), p->size());
        if (p->isWindow())
            break;
    }
    return r;
}

// Saves a screenshot a person looks at after the run, under the build tree
// (K528_BINARY_DIR/tests/screenshots/NAME, never the folder a test was
// started from), and says what is wrong with it: empty when it was saved and
// shows something. A picture of fewer than four colours is a window that did
// not paint (all background, all black), not a picture of its widgets: text,
// frames and buttons alone give dozens of colours with anti-aliasing.
[[nodiscard]] inline QString savedShotProblem(const QImage& shot, const QString& name) {
    if (shot.isNull())
        return QStringLiteral("%1: no picture").arg(name);
    const QImage img = shot.convertToFormat(QImage::Format_RGB32);
    QSet<QRgb> colours;
    for (int y = 0; y < img.height() && colours.size() < 4; ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(img.constScanLine(y));
        for (int x = 0; x < img.width() && colours.size() < 4; ++x)
            colours.insert(line[x]);
    }
    if (colours.size() < 4)
        return QStringLiteral("%1: a blank picture (%2 colours)").arg(name).arg(colours.size());
    const QString dir = QStringLiteral(K528_BINARY_DIR "/tests/screenshots");
    QDir().mkpath(QFileInfo(dir + QLatin1Char('/') + name).absolutePath());
    const QString path = dir + QLatin1Char('/') + name;
    if (!shot.save(path))
        return QStringLiteral("%1: cannot save %2").arg(name, path);
    return {};
}

[[nodiscard]] inline QString savedShotProblem(const QPixmap& shot, const QString& name) {
    return savedShotProblem(shot.toImage(), name);
}

} // namespace k528::testrig

// Saves a screenshot under the build tree and fails the test on a blank one.
#define K528_VERIFY_SHOT(picture, name)                                                      \
    do {                                                                                     \
        const QString shotProblem_ = ::k528::testrig::savedShotProblem((picture), (name));   \
        QVERIFY2(shotProblem_.isEmpty(), qPrintable(shotProblem_));                          \
    } while (false)
