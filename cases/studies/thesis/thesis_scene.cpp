#include "lexel/cases/studies/thesis/thesis_scene.h"

#include <cmath>

#include "lexel/cases/load/flatland_case.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace fs = std::filesystem;

flatland::PublishedTable ToPublishedTable(const ThesisTable& thesis) {
    flatland::PublishedTable table;
    table.title = thesis.title;
    for (const ThesisRow& row : thesis.rows)
        for (const std::string& method : row.methods)
            table.rows.push_back({row.label, method, row.angle, row.worst, row.average,
                                  row.meanPlusSigma, row.twoFrustaMean.value_or(NAN)});
    return table;
}

bool MatchesBetter(const flatland::TableAgreement& a, const flatland::TableAgreement& b) {
    if (a.worstNormalized != b.worstNormalized) return a.worstNormalized < b.worstNormalized;
    return a.rms < b.rms;
}

ThesisSceneChoice MeasureThesisScene(const fs::path& path, bool fitted,
                                     const flatland::PublishedTable& table) {
    ThesisSceneChoice choice;
    choice.path = path;
    choice.fitted = fitted;
    choice.scene = LoadFlatScene(path);
    try {
        choice.numbers = flatland::CompareWithTable(choice.scene, table);
    } catch (const DomainError& e) {
        throw FlatlandInputError(path.string(), e);
    }
    choice.agreement = flatland::Agreement(choice.numbers, {});
    return choice;
}

ThesisSceneChoice ChooseThesisScene(const ThesisTable& thesis, const fs::path& dir) {
    const flatland::PublishedTable table = ToPublishedTable(thesis);
    ThesisSceneChoice shipped = MeasureThesisScene(dir / thesis.file, false, table);
    const fs::path fittedPath = dir / "fitted" / thesis.file;
    if (!fs::exists(fittedPath)) return shipped;
    ThesisSceneChoice fitted = MeasureThesisScene(fittedPath, true, table);
    if (MatchesBetter(fitted.agreement, shipped.agreement)) {
        fitted.otherPath = shipped.path;
        fitted.otherAgreement = shipped.agreement;
        return fitted;
    }
    shipped.otherPath = fitted.path;
    shipped.otherAgreement = fitted.agreement;
    return shipped;
}

}  // namespace lexel::cases
