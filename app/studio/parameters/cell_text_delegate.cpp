#include "parameters/cell_text_delegate.h"

#include <QApplication>
#include <QFontMetrics>
#include <QPainter>
#include <QStyle>
#include <QTextLayout>
#include <algorithm>

namespace k528::studio {

namespace {

// Widths and texts seen while a table is resized or its language changes
// leave lines no cell shows any more: past this many the cache starts again.
constexpr qsizetype kMostShaped = 4096;
constexpr std::size_t kMostFonts = 16;

// Lays `layout` out in lines `width` wide, as the style lays out a cell.
void layOut(QTextLayout& layout, int width) {
    qreal y = 0;
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(width);
        line.setPosition(QPointF(0, y));
        y += line.height();
    }
    layout.endLayout();
}

} // namespace

struct CellTextDelegate::Shaped {
    QTextLayout layout; // the line drawn: elided, shaped, laid out
    QSize size;         // of the whole text laid out: where the style places the line
};

size_t qHash(const CellTextDelegate::Key& k, size_t seed) noexcept {
    return qHashMulti(seed, k.text, k.width, k.font, k.alignment, k.elide, k.rightToLeft);
}

CellTextDelegate::CellTextDelegate(QObject* parent) : QStyledItemDelegate(parent) {}

CellTextDelegate::~CellTextDelegate() = default;

const CellTextDelegate::Shaped* CellTextDelegate::shaped(const QStyleOptionViewItem& option, int width) const {
    auto font = std::find(fonts_.begin(), fonts_.end(), option.font);
    if (font == fonts_.end()) {
        if (fonts_.size() >= kMostFonts) {
            cache_.clear();
            fonts_.clear();
        }
        fonts_.push_back(option.font);
        font = fonts_.end() - 1;
    }
    const Key key{option.text,
                  width,
                  static_cast<int>(font - fonts_.begin()),
                  static_cast<int>(option.displayAlignment),
                  static_cast<int>(option.textElideMode),
                  option.direction == Qt::RightToLeft};
    if (const auto it = cache_.constFind(key); it != cache_.cend())
        return it->get();
    if (cache_.size() >= kMostShaped)
        cache_.clear();

    // What QCommonStyle does for a cell's text (viewItemDrawText): the whole
    // text laid out in the cell's width, elided when its one line is wider,
    // the line drawn laid out again in that width.
    QTextOption textOption;
    textOption.setWrapMode(QTextOption::ManualWrap);
    textOption.setTextDirection(option.direction);
    textOption.setAlignment(QStyle::visualAlignment(option.direction, option.displayAlignment));
    QTextLayout whole(option.text, option.font);
    whole.setTextOption(textOption);
    layOut(whole, width);
    std::shared_ptr<Shaped> s;
    if (whole.lineCount() == 1) {
        s = std::make_shared<Shaped>();
        s->size = whole.boundingRect().size().toSize();
        QString line = option.text;
        if (whole.lineAt(0).naturalTextWidth() > width)
            // TextLongestVariant: the text as it is (the style elides it with
            // no look for the variants a U+009C would separate).
            line = QFontMetrics(option.font).elidedText(option.text, option.textElideMode, width, Qt::TextLongestVariant);
        s->layout.setText(line);
        s->layout.setFont(option.font);
        s->layout.setTextOption(textOption);
        s->layout.setCacheEnabled(true); // keep the glyphs: drawing it again shapes nothing
        layOut(s->layout, width);
    }
    cache_.insert(key, s); // several lines: null, the style draws them
    return s.get();
}

void CellTextDelegate::paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const {
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    const QWidget* widget = opt.widget;
    const QStyle* style = widget ? widget->style() : QApplication::style();
    constexpr auto kNotPlain = QStyleOptionViewItem::WrapText | QStyleOptionViewItem::HasCheckIndicator |
                               QStyleOptionViewItem::HasDecoration;
    // The cell's text rectangle does not depend on its text when the whole
    // cell is shown selected (a table's): it is found with none. The current
    // cell of a view with the focus is left to the style: Fusion draws its
    // focus frame over the text, translucent.
    const bool plain = !opt.text.isEmpty() && !(opt.features & kNotPlain) && opt.showDecorationSelected &&
                       !(opt.state & (QStyle::State_Editing | QStyle::State_HasFocus)) &&
                       style->inherits("QFusionStyle");
    const Shaped* s = nullptr;
    QStyleOptionViewItem bare = opt;
    QRect textRect;
    if (plain) {
        bare.text.clear();
        const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, widget) + 1;
        textRect = style->subElementRect(QStyle::SE_ItemViewItemText, &bare, widget).adjusted(margin, 0, -margin, 0);
        s = shaped(opt, textRect.width());
    }
    if (!s) {
        style->drawControl(QStyle::CE_ItemViewItem, &opt, painter, widget);
        return;
    }
    // The background and the selection, then the text in the colour and
    // the place the style gives it.
    style->drawControl(QStyle::CE_ItemViewItem, &bare, painter, widget);
    QPalette::ColorGroup group = opt.state & QStyle::State_Enabled ? QPalette::Normal : QPalette::Disabled;
    if (group == QPalette::Normal && !(opt.state & QStyle::State_Active))
        group = QPalette::Inactive;
    painter->save();
    painter->setClipRect(opt.rect);
    painter->setPen(
        opt.palette.color(group, opt.state & QStyle::State_Selected ? QPalette::HighlightedText : QPalette::Text));
    const QRect placed = QStyle::alignedRect(Qt::LayoutDirectionAuto, opt.displayAlignment, s->size, textRect);
    s->layout.draw(painter, QPointF(textRect.x(), placed.top()));
    painter->restore();
}

} // namespace k528::studio
