/// @file app/mpi/tile_exchange.h
/// @brief The tiles one process rendered (RenderResult::tiles) as bytes, and the full result
/// put together from every process's bytes on rank 0. No MPI here: plain buffers.
#pragma once

#include "render/render.h"

#include <vector>

namespace kerf::app::mpi {

/// This process's tiles: for each, its number, then its film (with a filter wider than the
/// box) or its colour pixels (box), then its depth and normal pixels when asked for. Native
/// byte order: every rank runs the same executable on the same kind of machine.
std::vector<char> packTiles(const RenderResult& result);

/// Rebuilds the image of a whole render from the packed tiles of all the processes: `local`
/// gives the region, image size, filter and AOVs (every process's result has the same).
/// Throws std::runtime_error when a tile is missing or given twice.
RenderResult assembleTiles(const RenderResult& local, const std::vector<std::vector<char>>& packs);

}  // namespace kerf::app::mpi
