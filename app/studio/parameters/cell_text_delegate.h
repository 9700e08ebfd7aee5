// The cells of the parameter tables drawn as the style draws them, with each
// text shaped once. Qt's item view style lays out and shapes a cell's text
// several times on every paint (to measure it, to elide it, to draw it);
// a table of a few hundred short, fixed texts that typing into its search
// field repaints whole spent most of each keystroke there. The delegate
// keeps the shaped line, elided to its width, per text, width and font, and
// draws it where the style would. A cell that is not one plain line of text
// (an icon, a check box, wrapped or several lines, an editor open on it) or
// a style other than Fusion is painted by QStyledItemDelegate as before.
#pragma once

#include <QFont>
#include <QHash>
#include <QStyledItemDelegate>
#include <memory>
#include <vector>

class QTextLayout;

namespace k528::studio {

class CellTextDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit CellTextDelegate(QObject* parent = nullptr);
    ~CellTextDelegate() override;

    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override;

    // What the cache holds now (the benchmark and the tests look).
    int shapedTexts() const { return static_cast<int>(cache_.size()); }

    struct Key {
        QString text;
        int width = 0;
        int font = 0; // in fonts_
        int alignment = 0;
        int elide = 0;
        bool rightToLeft = false;
        bool operator==(const Key&) const = default;
    };

private:
    struct Shaped;
    // The line of `option.text` elided to `width` as the style would draw
    // it; null when it is not one line (the style draws it).
    const Shaped* shaped(const QStyleOptionViewItem& option, int width) const;

    mutable std::vector<QFont> fonts_;
    mutable QHash<Key, std::shared_ptr<const Shaped>> cache_;
};

size_t qHash(const CellTextDelegate::Key& k, size_t seed = 0) noexcept;

} // namespace k528::studio
