// The controls of a machine's control panel (pendant), drawn like the
// hardware: illuminated push-buttons, the latching mushroom E-stop, pilot
// lamps, the handwheel (manual pulse generator) and rotary selector switches.
// They only show and report; MachinePanelWidget connects them to the
// simulated machine. Each has a scale (1 = the sizes below): its size hints,
// legend plates and letters grow or shrink with it, so that the panel
// scales to the room it gets.
#pragma once

#include <QAbstractButton>
#include <QColor>
#include <QFont>
#include <QRectF>
#include <QStringList>
#include <QWidget>

namespace k528::studio {

// How a legend is set on its plate (`plate`: the plate's rectangle): the
// font, and a horizontal scale below 1 where even the smallest legible size
// is wider than the plate's room (the letters narrower, the word whole).
struct PlateText {
    QFont font;
    double xScale = 1;
    double room = 0; // the width the letters may take
};
PlateText plateText(const QRectF& plate, const QString& text);

// A 22 mm push-button with a coloured cap, optionally illuminated, and its
// legend plate below. Momentary: pressed() while the mouse holds it down,
// released() when it lets go (a jog moves for as long as it is held).
class PendantButton : public QAbstractButton {
    Q_OBJECT
public:
    enum class Cap { Green, Red, Yellow, Blue, Black, White };
    PendantButton(Cap cap, QWidget* parent = nullptr);

    void setLegend(const QString& legend); // on the plate below the cap
    QString legend() const { return legend_; }
    void setSymbol(const QString& symbol); // on the cap itself (arrows)
    void setLit(bool lit);
    bool lit() const { return lit_; }
    void setIlluminated(bool illuminated) { illuminated_ = illuminated; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    void setScale(double scale);
    double scale() const { return scale_; }
    QRectF capRect() const; // where a test clicks
    QRectF legendPlate() const; // the plate below the cap

protected:
    void paintEvent(QPaintEvent*) override;
    bool hitButton(const QPoint& pos) const override;

private:
    double scale_ = 1;
    Cap cap_;
    QString legend_, symbol_;
    bool lit_ = false, illuminated_ = false;
};

// The emergency stop: a red mushroom on a yellow disc. It latches when
// pressed and is released by a second click («pull to release»).
class MushroomButton : public QAbstractButton {
    Q_OBJECT
public:
    explicit MushroomButton(QWidget* parent = nullptr);
    void setLegend(const QString& legend);
    QString legend() const { return legend_; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    void setScale(double scale);
    double scale() const { return scale_; }

protected:
    void paintEvent(QPaintEvent*) override;
    bool hitButton(const QPoint& pos) const override;

private:
    double scale_ = 1;
    QString legend_;
};

// A pilot lamp with its legend.
class PilotLamp : public QWidget {
    Q_OBJECT
public:
    enum class Color { Green, Red, Amber, White, Blue };
    PilotLamp(Color color, QWidget* parent = nullptr);
    void setLegend(const QString& legend);
    QString legend() const { return legend_; }
    QRectF legendPlate() const; // the plate below the lens
    void setOn(bool on);
    bool isOn() const { return on_; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    void setScale(double scale);
    double scale() const { return scale_; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    double scale_ = 1;
    Color color_;
    QString legend_;
    bool on_ = false;
};

// The handwheel: a dial with `detentsPerTurn` graduations. Drag it round
// with the mouse or turn the mouse wheel; each detent passed is reported.
class HandwheelDial : public QWidget {
    Q_OBJECT
public:
    explicit HandwheelDial(QWidget* parent = nullptr);
    void setDetentsPerTurn(int n);
    int detentsPerTurn() const { return detents_; }
    double angleDegrees() const { return angle_; }
    void setEnabledLook(bool active); // greyed while no axis is selected
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    void setScale(double scale);
    double scale() const { return scale_; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override { return w; }

signals:
    void turned(int detents); // + clockwise

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

private:
    double scale_ = 1;
    double pointerAngle(const QPointF& p) const;
    void rotateBy(double degrees);
    int detents_ = 100;
    double angle_ = 0;     // where the dial stands (degrees, clockwise from top)
    double pending_ = 0;   // degrees not yet a whole detent
    double grabAngle_ = 0; // pointer angle at the last move
    bool dragging_ = false, active_ = true;
};

// A rotary selector switch: a knob with a pointer and its positions' legends
// around it. Click a legend to select it, click the knob to step on, or
// turn the mouse wheel.
class SelectorSwitch : public QWidget {
    Q_OBJECT
public:
    explicit SelectorSwitch(QWidget* parent = nullptr);
    void setPositions(const QStringList& legends, double spanDegrees = 90);
    QStringList positions() const { return legends_; }
    void setCaption(const QString& caption);
    QString caption() const { return caption_; }
    QRectF captionPlate() const; // the plate above the switch
    int position() const { return position_; }
    void setPosition(int index);           // emits positionChanged when it changes
    QPointF legendCentre(int index) const; // for tests
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    void setScale(double scale);
    double scale() const { return scale_; }

signals:
    void positionChanged(int index);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

private:
    double scale_ = 1;
    QPointF centre() const;
    double knobRadius() const;
    double angleOf(int index) const; // degrees clockwise from the top
    QStringList legends_;
    QString caption_;
    double span_ = 90;
    int position_ = 0;
};

} // namespace k528::studio
