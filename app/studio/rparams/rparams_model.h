// The R-parameters R0..R299 of the simulated controller (section 2.5,
// appendix Л) as a table: number, access, preset group (УСТ 1..9), meaning,
// value in discretes and in mm (mm/min, s) of its axis, and the preset the
// machine keeps for it. Live: refresh() on every advance redraws the values
// that changed. Values are edited where the engine allows it, as on the
// K923's РУЧНОЙ screen 3 (Controller::setR: not R232..R262, not while a
// program executes); the mm column takes millimetres for coordinates.
#pragma once

#include <QAbstractTableModel>
#include <QSortFilterProxyModel>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace k528::engine {
class Controller;
}

namespace k528::studio {

class SimulationSession;

class RParamsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Number, Access, Group, Meaning, Value, Mm, Preset, ColumnCount };
    static constexpr int NumberRole = Qt::UserRole;
    static constexpr int SearchRole = Qt::UserRole + 1;

    explicit RParamsModel(SimulationSession& session, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation o, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // Sets R`number` on the controller: "" when done, otherwise why not.
    QString setValue(int number, std::int64_t value);
    // "" when R`number` may be edited now, otherwise why not.
    QString whyNotEditable(int number) const;

    const std::map<int, std::int64_t>& presets() const { return presets_; }
    void setPresets(std::map<int, std::int64_t> presets);

public slots:
    void refresh();
    void retranslate();

signals:
    void refused(const QString& why);

private:
    QString mmText(int number, std::int64_t v) const;
    SimulationSession& session_;
    std::array<std::int32_t, 300> shown_{};
    std::map<int, std::int64_t> presets_;
    std::vector<QString> search_;
    bool russian_ = false;
};

class RParamsFilter : public QSortFilterProxyModel {
    Q_OBJECT
public:
    enum class Show { All, User, System, ReadOnly, Presets, NonZero };
    explicit RParamsFilter(QObject* parent = nullptr);
    void setSearch(const QString& text);
    void setShow(Show s);

protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override;

private:
    QStringList words_;
    Show show_ = Show::All;
};

} // namespace k528::studio
