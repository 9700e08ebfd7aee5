// A row of controls that wraps onto more rows when its pane is narrow (a
// dock's tool row: the oscilloscope's, the backplot's), so that the pane's
// minimum width is its widest control, not the whole row. Items keep their
// size hints; the layout has a height for each width.
#pragma once

#include <QLayout>
#include <QList>

namespace k528::studio {

class FlowLayout : public QLayout {
public:
    explicit FlowLayout(QWidget* parent = nullptr, int hSpacing = 6, int vSpacing = 4);
    ~FlowLayout() override;

    // A few widgets kept together on one row (a label and its field).
    void addGroup(std::initializer_list<QWidget*> widgets);

    void addItem(QLayoutItem* item) override;
    int count() const override { return static_cast<int>(items_.size()); }
    QLayoutItem* itemAt(int index) const override { return items_.value(index); }
    QLayoutItem* takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override { return arrange(QRect(0, 0, width, 0), false); }
    QSize minimumSize() const override;
    QSize sizeHint() const override;
    void setGeometry(const QRect& rect) override;

private:
    int arrange(const QRect& rect, bool apply) const;
    QList<QLayoutItem*> items_;
    int hSpacing_, vSpacing_;
};

} // namespace k528::studio
