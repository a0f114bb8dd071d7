// `lexel storage`: Lloyd et al. 2006's storage factor for one view frustum (the data of Figs. 5–7,
// 10, 12, 13) as terminal text, one JSON document, CSV and PNG figures; and for a 3D case the
// measured storage factor of every method beside the analytic S̄ of its scheme (schemas in
// README.md here).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "lexel/cases/studies/storage/storage_study.h"

namespace lexel::cases {

std::string StorageText(const StorageStudy& study);
nlohmann::json StorageJson(const StorageStudy& study);
// One row per plotted value: figure,series,x1,x2,value (the columns per figure: README.md).
std::string StorageCsv(const StorageStudy& study);
// fig5_6_warp.png, fig7_hemisphere_{no_warp,lispsm,fp_w}.png, fig10_partitions.png,
// fig12_maps.png, fig13_crossover.png in `dir` (which must exist); returns the file names.
// Throws std::runtime_error when a file cannot be written.
std::vector<std::string> WriteStorageFigures(const std::filesystem::path& dir,
                                             const StorageStudy& study);

std::string CaseStorageText(const CaseStorage& result);
nlohmann::json CaseStorageJson(const CaseStorage& result);
// light,method,maps,texels,max_perspective_aliasing,storage_factor,storage_factor_p99,scheme,
// scheme_storage_camera,scheme_storage_visible,optimal_camera,optimal_visible
std::string CaseStorageCsv(const CaseStorage& result);
// The columns of `storage --case`'s rows (JSON and CSV) as a Markdown table: cases/README.md's
// list.
std::string CaseStorageColumnReference();

}  // namespace lexel::cases
