#include "render/Film.h"

namespace lancer {

Film::Film(int width, int height)
    : width_(width),
      height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}

}  // namespace lancer
