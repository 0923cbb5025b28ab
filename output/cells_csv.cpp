#include "output/cells_csv.hpp"

#include "output/outward_decimal.hpp"
#include "output/packing_fraction.hpp"

namespace ellvor {

const char* const kCellsCsvHeader =
    "site,visible,area_lo,area_hi,site_area,packing_fraction_lo,packing_fraction_hi,perimeter_lo,perimeter_hi,"
    "neighbors";

std::string neighbor_label(const CellSide& side) {
    if (side.neighbor < 0) return std::string("wall:") + wall_name(side.wall);
    std::string label = std::to_string(side.neighbor);
    if (side.shift[0] != 0 || side.shift[1] != 0)
        label += "@" + std::to_string(side.shift[0]) + "," + std::to_string(side.shift[1]);
    return label;
}

void write_cells_csv(std::ostream& out, const CellTessellation& cells) {
    out << kCellsCsvHeader << "\n";
    for (const Cell& c : cells.cells) {
        const DecimalBounds area = decimal_bounds(c.area), perimeter = decimal_bounds(c.perimeter);
        const std::optional<Ball> fraction = packing_fraction(c);
        const DecimalBounds pf = fraction ? decimal_bounds(*fraction) : DecimalBounds{};
        std::string neighbors;
        bool quoted = false;
        for (const CellSide& side : c.sides) {
            const std::string label = neighbor_label(side);
            quoted = quoted || label.find(',') != std::string::npos;
            neighbors += (neighbors.empty() ? "" : " ") + label;
        }
        // RFC 4180: a field holding a comma (a periodic shift) is quoted.
        if (quoted) neighbors = "\"" + neighbors + "\"";
        out << c.site << "," << (c.visible ? 1 : 0) << "," << area.lo << "," << area.hi << ","
            << certain_digits(c.site_area) << "," << pf.lo << "," << pf.hi << "," << perimeter.lo << ","
            << perimeter.hi << "," << neighbors << "\n";
    }
}

}  // namespace ellvor
