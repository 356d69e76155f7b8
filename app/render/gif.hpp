#pragma once

#include <filesystem>
#include <vector>

#include "render/image.hpp"

namespace nome::render {

// Writes the frames (all of one size) as an animated GIF that loops forever, `delay_ms` per frame, with
// giflib: each frame quantised to its own 256-colour table (GifQuantizeBuffer). Atomic
// (write_file_atomically). Throws InvalidInputError for no frames or frames of different sizes, IoError
// when giflib fails.
void write_gif(const std::filesystem::path& path, const std::vector<Image>& frames, int delay_ms);

}  // namespace nome::render
