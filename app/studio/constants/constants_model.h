// The 152 machine constants of the simulated controller as a table (table
// Е.1 beside the values): number, axis, panel name, meaning, unit, range,
// address in the positioner, value, and what the value means (mm, m/s², V,
// the channel ... — db::explainCValue over core's units). The value column
// is editable through ConstantsEditor (checked, undoable, kept). The filter
// (ConstantsFilter) searches every text of a row and narrows by axis.
#pragma once

#include "parameters/parameter_table_model.h"

#include <array>
#include <cstdint>
#include <vector>

namespace k528::studio {

class ConstantsEditor;

class ConstantsModel : public ParameterTableModel {
    Q_OBJECT
public:
    enum Column { Number, Axis, Name, Meaning, Unit, Range, Address, Value, Means, ColumnCount };

    explicit ConstantsModel(ConstantsEditor& editor, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    // Value column: the number typed (whole, in the table's unit); refused
    // changes return false and ConstantsEditor::refused() says why.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // The row of C`number`.
    static int rowOf(int number) { return number - 1; }
    ConstantsEditor& editor() const { return editor_; }

public slots:
    // Follows the controller: rows whose value changed (and every meaning,
    // which depends on other constants) are redrawn.
    void refresh() override;
    void retranslate() override;

protected:
    QStringList columnTitles() const override;
    QStringList columnToolTips() const override;

private:
    void fillTexts();
    void fillMeans();
    ConstantsEditor& editor_;
    std::array<std::int64_t, 153> shown_{};
    std::vector<QString> means_;
    std::vector<QString> search_;
    // The fixed texts of each row in the UI language (painting asks often).
    std::vector<std::array<QString, ColumnCount>> cells_;
};

class ConstantsFilter : public ParameterFilter {
    Q_OBJECT
public:
    enum class AxisFilter { All, X, Z, Common };
    explicit ConstantsFilter(QObject* parent = nullptr);
    void setAxisFilter(AxisFilter a);
    void setHideReserved(bool hide);

protected:
    bool keeps(int row, const QModelIndex& parent) const override;

private:
    AxisFilter axis_ = AxisFilter::All;
    bool hideReserved_ = false;
};

} // namespace k528::studio
