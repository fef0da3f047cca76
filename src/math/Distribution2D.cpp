#include "math/Distribution2D.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lancer {

namespace {

std::vector<Distribution1D> makeRows(const std::vector<float>& values, int width, int height) {
    if (width < 1 || height < 1 ||
        values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
        throw std::invalid_argument("Distribution2D: width * height values expected");
    std::vector<Distribution1D> rows;
    rows.reserve(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) {
        const auto first = values.begin() + static_cast<std::ptrdiff_t>(y) * width;
        rows.emplace_back(std::vector<float>(first, first + width));
    }
    return rows;
}

// Each row's integral: a row of zeros, which its Distribution1D makes uniform, keeps weight 0.
std::vector<float> rowIntegrals(const std::vector<float>& values, int width) {
    std::vector<float> integrals;
    for (std::size_t begin = 0; begin < values.size(); begin += static_cast<std::size_t>(width)) {
        double sum = 0;
        for (std::size_t i = begin; i < begin + static_cast<std::size_t>(width); ++i)
            sum += values[i];
        integrals.push_back(static_cast<float>(sum / width));
    }
    return integrals;
}

std::size_t cellOf(float x, int count) {
    return std::min(static_cast<std::size_t>(std::max(x, 0.0f) * static_cast<float>(count)),
                    static_cast<std::size_t>(count - 1));
}

}  // namespace

Distribution2D::Distribution2D(const std::vector<float>& values, int width, int height)
    : width_(width),
      height_(height),
      rows_(makeRows(values, width, height)),
      marginal_(rowIntegrals(values, width)) {}

Distribution2D::CellSample Distribution2D::sampleCell(const Vec2& u) const {
    // The row by its index, so that the column comes from the row whose probability is stated.
    CellSample cell;
    float rowProbability = 0, columnProbability = 0;
    const std::size_t row = marginal_.sampleDiscrete(u.y, &rowProbability, &cell.offset.y);
    const std::size_t column = rows_[row].sampleDiscrete(u.x, &columnProbability, &cell.offset.x);
    cell.x = static_cast<int>(column);
    cell.y = static_cast<int>(row);
    cell.probability = rowProbability * columnProbability;
    return cell;
}

Vec2 Distribution2D::sample(const Vec2& u, float* pdf) const {
    const CellSample cell = sampleCell(u);
    // (cell + offset) / size may round up to the next cell's edge: the point stays in its cell.
    const auto place = [](int index, float offset, int count) {
        const float n = static_cast<float>(count);
        return std::min((static_cast<float>(index) + offset) / n,
                        std::nextafter(static_cast<float>(index + 1) / n, 0.0f));
    };
    *pdf = cell.probability * static_cast<float>(width_) * static_cast<float>(height_);
    return {place(cell.x, cell.offset.x, width_), place(cell.y, cell.offset.y, height_)};
}

float Distribution2D::pdf(const Vec2& p) const {
    return marginal_.pdf(p.y) * rows_[cellOf(p.y, height_)].pdf(p.x);
}

}  // namespace lancer
