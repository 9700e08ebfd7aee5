#include "rparams/rparams_model.h"

#include "catalog/rparams.h"
#include "engine/positioner.h"
#include "engine/rparams.h"
#include "session/catalog_texts.h"
#include "window_language.h"
#include "controller/controller.h"
#include "units/units.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <QLocale>
#include <QPointer>
#include <cmath>
#include <memory>

namespace k528::studio {

namespace {

QString fromStd(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

units::AxisScale scaleOf(const Controller& c, catalog::RUnit u) {
    return profile::axisScale(c.profile(), catalog::rUnitAxis(u) == catalog::Axis::Z ? catalog::Axis::Z
                                                                                     : catalog::Axis::X);
}

bool isCoordinate(catalog::RUnit u) {
    return u == catalog::RUnit::DiscX || u == catalog::RUnit::DiscZ;
}

} // namespace

RParamsModel::RParamsModel(ViewedController& viewed, QObject* parent)
    : ParameterTableModel(ColumnCount, parent), viewed_(viewed) {
    const auto r = controller().rValues();
    std::copy(r.begin(), r.begin() + std::min<std::ptrdiff_t>(300, static_cast<std::ptrdiff_t>(r.size())), shown_.begin());
    presets_ = controller().profile().r;
    retranslate();
}

Controller& RParamsModel::controller() const { return viewed_.current(); }

void RParamsModel::retranslate() {
    beginResetModel();
    search_.assign(engine::kRCount, QString());
    for (int n = 0; n < engine::kRCount; ++n) {
        const catalog::RParamDef& d = catalog::rParam(n);
        QString s = QStringLiteral("r%1 %1 ").arg(n);
        for (std::string_view t : {d.meaningRu, d.meaningEn, d.panelHint, catalog::rGroupNameRu(d.group),
                                   catalog::rGroupNameEn(d.group)})
            s += fromStd(t) + ' ';
        search_[static_cast<std::size_t>(n)] = s.toLower();
    }
    endResetModel();
}

void RParamsModel::setPresets(std::map<int, std::int64_t> presets) {
    presets_ = std::move(presets);
    emit dataChanged(index(0, Preset), index(engine::kRCount - 1, Preset));
}

void RParamsModel::refresh() {
    const auto r = controller().rValues();
    const auto [first, last] = takeChanged(r, shown_, 0, std::min(engine::kRCount, static_cast<int>(r.size())));
    if (first >= 0)
        emit dataChanged(index(first, Value), index(last, Mm));
}

int RParamsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : engine::kRCount;
}

QString RParamsModel::mmText(int number, std::int64_t v) const {
    const catalog::RParamDef& d = catalog::rParam(number);
    const Controller& c = controller();
    switch (d.unit) {
    case catalog::RUnit::DiscX:
    case catalog::RUnit::DiscZ: {
        const units::AxisScale s = scaleOf(c, d.unit);
        return QString::number(units::discToMm(v, s), 'f', s.decimals());
    }
    case catalog::RUnit::DiscXPerMin:
    case catalog::RUnit::DiscZPerMin: {
        const units::AxisScale s = scaleOf(c, d.unit);
        return tr("%1 mm/min").arg(units::discToMm(v, s), 0, 'f', std::max(0, s.decimals() - 2));
    }
    case catalog::RUnit::Ms:
        return tr("%1 s").arg(units::msToS(v), 0, 'f', 3);
    default:
        return {};
    }
}

QVariant RParamsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() < 0 || index.row() >= engine::kRCount)
        return {};
    const int n = index.row();
    const catalog::RParamDef& d = catalog::rParam(n);
    if (role == NumberRole)
        return n;
    if (role == SearchRole)
        return search_[static_cast<std::size_t>(n)];
    const std::int64_t v = shown_[static_cast<std::size_t>(n)];
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case Number:
            return role == Qt::EditRole ? QVariant(n) : QVariant(QStringLiteral("R%1").arg(n));
        case Access:
            switch (d.access) {
            case catalog::RAccess::User:
                return tr("user");
            case catalog::RAccess::System:
                return tr("system");
            case catalog::RAccess::ReadOnly:
                return tr("read only");
            case catalog::RAccess::Unassigned:
                return tr("reserved");
            }
            return {};
        case Group:
            return d.group == 0 ? QString()
                                : QStringLiteral("УСТ %1 %2").arg(d.group).arg(rGroupName(d.group));
        case Meaning: {
            QString m = coreText(d.meaningRu, d.meaningEn);
            const QString unit = coreText(catalog::rUnitRu(d.unit), catalog::rUnitEn(d.unit));
            if (!unit.isEmpty() && d.unit != catalog::RUnit::Number)
                m += QStringLiteral(" [%1]").arg(unit);
            return m;
        }
        case Value:
            return QString::number(v);
        case Mm:
            return mmText(n, v);
        case Preset: {
            const auto it = presets_.find(n);
            return it == presets_.end() ? QString() : QString::number(it->second);
        }
        default:
            return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        QString t = coreText(d.meaningRu, d.meaningEn);
        if (!d.panelHint.empty())
            t += QStringLiteral("\n") + fromStd(d.panelHint);
        if (const QString note = coreText({}, d.note); !note.isEmpty()) // the catalog's notes are English only
            t += QStringLiteral("\n") + note;
        return t;
    }
    if (role == Qt::TextAlignmentRole && (index.column() == Value || index.column() == Mm || index.column() == Preset))
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && (d.readOnly() || d.access == catalog::RAccess::Unassigned))
        return QBrush(QColor(0x70, 0x70, 0x70));
    if (role == Qt::FontRole && index.column() == Value)
        return valueFont();
    return {};
}

QStringList RParamsModel::columnTitles() const {
    return {tr("No."),       tr("Access"), tr("Preset screen"), tr("Meaning (appendix L)"),
            tr("Discretes"), tr("mm"),     tr("Preset")};
}

QString RParamsModel::whyNotEditable(int number) const {
    return controller().whyNotWritable(MemoryArea::R, number);
}

Qt::ItemFlags RParamsModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (!index.isValid() || engine::rReadOnly(index.row()))
        return f;
    if (index.column() == Value ||
        (index.column() == Mm && isCoordinate(catalog::rParam(index.row()).unit)))
        f |= Qt::ItemIsEditable;
    return f;
}

void RParamsModel::setValue(int number, std::int64_t value, std::function<void(const QString&)> done) {
    const auto answer = [done](const QString& why) {
        if (done)
            done(why);
    };
    if (const QString why = whyNotEditable(number); !why.isEmpty())
        return answer(why);
    if (!engine::fitsR(value))
        return answer(tr("%1 is outside the R-parameters' range -2147483648..2147483647").arg(value));
    QPointer<RParamsModel> self(this);
    controller().setR(number, value, [self, answer](bool ok, const QString& why) {
        if (ok && self)
            self->refresh();
        answer(ok ? QString() : why);
    });
}

bool RParamsModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !index.isValid())
        return false;
    const int n = index.row();
    const QString text = value.toString().trimmed();
    std::int64_t v = 0;
    bool ok = false;
    if (index.column() == Value) {
        v = text.toLongLong(&ok);
    } else if (index.column() == Mm && isCoordinate(catalog::rParam(n).unit)) {
        const double mm = QLocale::c().toDouble(QString(text).replace(QLatin1Char(','), QLatin1Char('.')), &ok);
        if (ok && std::isfinite(mm) && std::fabs(mm) < 1e9)
            v = units::mmToDisc(mm, scaleOf(controller(), catalog::rParam(n).unit));
        else
            ok = false;
    } else {
        return false;
    }
    if (!ok) {
        emit refused(tr("R%1: «%2» is not a number").arg(n).arg(text));
        return false;
    }
    auto refusedNow = std::make_shared<bool>(false);
    QPointer<RParamsModel> self(this);
    setValue(n, v, [self, refusedNow](const QString& why) {
        if (why.isEmpty() || !self)
            return;
        *refusedNow = true; // the simulation answers at once: setData returns false
        emit self->refused(why);
    });
    return !*refusedNow;
}

RParamsFilter::RParamsFilter(QObject* parent) : ParameterFilter(parent) {}

void RParamsFilter::setShow(Show s) {
    show_ = s;
    invalidateFilter();
}

bool RParamsFilter::keeps(int row, const QModelIndex& parent) const {
    const catalog::RParamDef* d = catalog::findRParam(row);
    if (!d)
        return false;
    const auto cell = [&](int column) { return sourceModel()->index(row, column, parent).data().toString(); };
    switch (show_) {
    case Show::All: return true;
    case Show::User: return d->user();
    case Show::System: return d->access == catalog::RAccess::System;
    case Show::ReadOnly: return d->readOnly();
    case Show::Presets: return !cell(RParamsModel::Preset).isEmpty();
    case Show::NonZero: return cell(RParamsModel::Value) != QLatin1String("0");
    }
    return true;
}

} // namespace k528::studio
