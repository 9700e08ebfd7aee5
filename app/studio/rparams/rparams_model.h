// The R-parameters R0..R299 of the controller the window shows (section 2.5,
// appendix Л) as a table: number, access, preset group (УСТ 1..9), meaning,
// value in discretes and in mm (mm/min, s) of its axis, and the preset the
// machine keeps for it. Live: refresh() on every update of the controller
// redraws the values that changed. Values are edited with the controller's
// rules (Controller::setR: the simulation as on the K923's РУЧНОЙ screen 3 —
// not R232..R262, not while a program executes; a real controller in F7
// «РАБОТА С ПЭВМ», R0..R231 but R158, R222, R223); the mm column takes
// millimetres for coordinates.
#pragma once

#include "parameters/parameter_table_model.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <functional>

namespace k528::studio {

class Controller;
class ViewedController;

class RParamsModel : public ParameterTableModel {
    Q_OBJECT
public:
    enum Column { Number, Access, Group, Meaning, Value, Mm, Preset, ColumnCount };

    explicit RParamsModel(ViewedController& viewed, QObject* parent = nullptr);
    Controller& controller() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // Asks the controller to set R`number`; `done` gets "" when it did,
    // otherwise why not (at once for the simulation, when the line answered
    // for a real controller).
    void setValue(int number, std::int64_t value, std::function<void(const QString& why)> done = {});
    // "" when R`number` may be edited now, otherwise why not.
    QString whyNotEditable(int number) const;

    const std::map<int, std::int64_t>& presets() const { return presets_; }
    void setPresets(std::map<int, std::int64_t> presets);

public slots:
    void refresh() override;
    void retranslate() override;

signals:
    void refused(const QString& why);

protected:
    QStringList columnTitles() const override;

private:
    QString mmText(int number, std::int64_t v) const;
    ViewedController& viewed_;
    std::array<std::int32_t, 300> shown_{};
    std::map<int, std::int64_t> presets_;
    std::vector<QString> search_;
};

class RParamsFilter : public ParameterFilter {
    Q_OBJECT
public:
    enum class Show { All, User, System, ReadOnly, Presets, NonZero };
    explicit RParamsFilter(QObject* parent = nullptr);
    void setShow(Show s);

protected:
    bool keeps(int row, const QModelIndex& parent) const override;

private:
    Show show_ = Show::All;
};

} // namespace k528::studio
