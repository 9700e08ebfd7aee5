#include "constants/constants_model.h"

#include "catalog/cparams.h"
#include "constants/constants_editor.h"
#include "db/explain.h"
#include "engine/positioner.h"
#include "window_language.h"
#include "controller/controller.h"

#include <QBrush>
#include <QColor>
#include <QFont>

namespace k528::studio {

namespace {

QString fromStd(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

const catalog::CParamDef& defAt(int row) {
    return catalog::cParams()[static_cast<std::size_t>(row)];
}

} // namespace

ConstantsModel::ConstantsModel(ConstantsEditor& editor, QObject* parent)
    : ParameterTableModel(ColumnCount, parent), editor_(editor) {
    const auto c = editor_.values();
    std::copy(c.begin(), c.begin() + 153, shown_.begin());
    fillTexts();
    fillMeans();
    connect(&editor_, &ConstantsEditor::changed, this, &ConstantsModel::refresh);
}

void ConstantsModel::fillTexts() {
    search_.assign(catalog::kCParamCount, QString());
    cells_.assign(catalog::kCParamCount, {});
    for (int row = 0; row < catalog::kCParamCount; ++row) {
        const catalog::CParamDef& d = defAt(row);
        auto& cell = cells_[static_cast<std::size_t>(row)];
        cell[Number] = QStringLiteral("C%1").arg(d.number, 3, 10, QChar('0'));
        cell[Axis] = fromStd(catalog::axisName(d.axis));
        cell[Name] = fromStd(d.name); // as the K923 shows it
        // The first words (the tooltip has all): a table cell shows about
        // 40 characters, and shaping the whole text for every paint would
        // cost more than the filter itself.
        QString meaning = coreText(d.descriptionRu, d.descriptionEn);
        if (meaning.size() > 72) {
            const qsizetype cut = meaning.lastIndexOf(QLatin1Char(' '), 70);
            meaning = meaning.left(cut > 20 ? cut : 70) + QStringLiteral(" …");
        }
        cell[Meaning] = meaning;
        cell[Unit] = coreText(catalog::unitRu(d.unit), catalog::unitEn(d.unit));
        cell[Range] = QStringLiteral("%1…%2").arg(d.min).arg(d.max);
        cell[Address] = coreText(d.address.text(), d.address.textEn());
        QString s = QStringLiteral("c%1 c%2 %2 ").arg(d.number, 3, 10, QChar('0')).arg(d.number);
        s += fromStd(catalog::axisName(d.axis)) + ' ';
        for (std::string_view t : {d.name, d.nameEn, d.descriptionRu, d.descriptionEn, d.hintRu,
                                   d.hintEn, catalog::unitRu(d.unit), catalog::unitEn(d.unit)})
            s += fromStd(t) + ' ';
        s += fromStd(d.address.text());
        search_[static_cast<std::size_t>(row)] = s.toLower();
    }
}

void ConstantsModel::fillMeans() {
    const profile::MachineProfile& p = editor_.controller().profile();
    const db::Lang lang = inWindowLanguage(db::Lang::Ru, db::Lang::En); // core explains in it
    means_.assign(catalog::kCParamCount, QString());
    for (int row = 0; row < catalog::kCParamCount; ++row)
        means_[static_cast<std::size_t>(row)] = fromStd(db::explainCValue(p, row + 1, lang));
}

void ConstantsModel::refresh() {
    const auto [first, last] = takeChanged(editor_.values(), shown_, 1, catalog::kCParamCount + 1);
    if (first < 0)
        return;
    fillMeans();
    emit dataChanged(index(rowOf(first), Value), index(rowOf(last), Value));
    emit dataChanged(index(0, Means), index(catalog::kCParamCount - 1, Means));
}

void ConstantsModel::retranslate() {
    beginResetModel();
    fillTexts();
    fillMeans();
    endResetModel();
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

int ConstantsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : catalog::kCParamCount;
}

QVariant ConstantsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() < 0 || index.row() >= catalog::kCParamCount)
        return {};
    const catalog::CParamDef& d = defAt(index.row());
    if (role == NumberRole)
        return d.number;
    if (role == SearchRole)
        return search_[static_cast<std::size_t>(index.row())];
    const std::int64_t v = shown_[static_cast<std::size_t>(d.number)];
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case Number:
            if (role == Qt::EditRole)
                return d.number;
            [[fallthrough]];
        case Axis:
        case Name:
        case Meaning:
        case Unit:
        case Range:
        case Address:
            return cells_[static_cast<std::size_t>(index.row())][static_cast<std::size_t>(index.column())];
        case Value:
            return QString::number(v);
        case Means:
            return means_[static_cast<std::size_t>(index.row())];
        default:
            return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        // The name as the K923 shows it; an English window adds our English
        // name, and the transcription's notes (English only: the catalog's,
        // about how the manual was read).
        QString t = QStringLiteral("<b>C%1 %2</b>").arg(d.number, 3, 10, QChar('0')).arg(fromStd(d.name).toHtmlEscaped());
        if (const QString nameEn = coreText({}, d.nameEn); !nameEn.isEmpty())
            t += QStringLiteral(" (%1)").arg(nameEn.toHtmlEscaped());
        t += QStringLiteral("<br>") + coreText(d.descriptionRu, d.descriptionEn).toHtmlEscaped();
        if (const QString hint = coreText(d.hintRu, d.hintEn); !hint.isEmpty())
            t += QStringLiteral("<br><i>%1</i>").arg(hint.toHtmlEscaped());
        if (const QString note = coreText({}, d.note); !note.isEmpty())
            t += QStringLiteral("<br><small>%1</small>").arg(note.toHtmlEscaped());
        return t;
    }
    if (role == Qt::TextAlignmentRole && (index.column() == Value || index.column() == Range))
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && d.reserved())
        return QBrush(QColor(0x80, 0x80, 0x80));
    if (role == Qt::FontRole && index.column() == Value)
        return valueFont();
    return {};
}

QStringList ConstantsModel::columnTitles() const {
    return {tr("No."),   tr("Axis"),    tr("Panel name"), tr("Meaning"),        tr("Unit"),
            tr("Range"), tr("Address"), tr("Value"),      tr("The value means")};
}

QStringList ConstantsModel::columnToolTips() const {
    QStringList tips(ColumnCount);
    // The manual's column «Адрес в БП»: the title alone would not say whose memory.
    tips[Address] = tr("Where the constant lives in the positioner's memory, as table E.1 prints it: "
                       "the word Z…, its bit or byte");
    return tips;
}

Qt::ItemFlags ConstantsModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == Value && !defAt(index.row()).reserved())
        f |= Qt::ItemIsEditable;
    return f;
}

bool ConstantsModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !index.isValid() || index.column() != Value)
        return false;
    const int number = defAt(index.row()).number;
    bool ok = false;
    const qlonglong v = value.toString().trimmed().toLongLong(&ok);
    if (!ok) {
        emit editor_.refused(tr("C%1: «%2» is not a whole number").arg(number, 3, 10, QChar('0')).arg(value.toString()));
        return false;
    }
    return editor_.set(number, v);
}

ConstantsFilter::ConstantsFilter(QObject* parent) : ParameterFilter(parent) {}

void ConstantsFilter::setAxisFilter(AxisFilter a) {
    axis_ = a;
    invalidateFilter();
}

void ConstantsFilter::setHideReserved(bool hide) {
    hideReserved_ = hide;
    invalidateFilter();
}

bool ConstantsFilter::keeps(int row, const QModelIndex& parent) const {
    const QModelIndex i = sourceModel()->index(row, 0, parent);
    const catalog::CParamDef* d = catalog::findCParam(i.data(ConstantsModel::NumberRole).toInt());
    if (!d)
        return false;
    if (hideReserved_ && d->reserved())
        return false;
    // The axis each choice after All keeps, in the order of AxisFilter.
    static constexpr catalog::Axis kAxisOf[] = {catalog::Axis::X, catalog::Axis::Z, catalog::Axis::Common};
    return axis_ == AxisFilter::All || d->axis == kAxisOf[static_cast<int>(axis_) - 1];
}

} // namespace k528::studio
