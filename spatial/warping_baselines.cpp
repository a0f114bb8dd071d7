// The perspective-warping baselines: LiSPSM and PSM (see baselines.h for the papers).
//
// Both build a classic world-space 4×4 whose rows 1, 2, 4 send world points to the map, convert it
// with FromScreenRows (which checks that it sends the light to infinity, report Fig. 1) and keep
// only its optical axis p4: the affine part is refitted with FitMapToPoints over the focus body B
// (view frustum ∩ scene bounds, LiSPSM's "body") and the relevant points, exactly as the report
// fits every candidate (report §2.3 step 4b-ii). Both fall back to the focused map, with the
// reason in BaselineDiagnostics::fallback, when their construction degenerates or leaves a
// relevant point behind the light or outside the map.
//
// LiSPSM (Wimmer, Scherzer & Purgathofer, EGSR 2004; Lloyd et al. 2006 §4.1, Fig. 3). For a
// directional light travelling along l: the warp is a perspective frustum whose axis f is the view
// direction v projected perpendicular to l (sin γ = |v × l|), whose projection centre c lies n_opt
// before the body's near face along f, n_opt = (z_n + √(z_f z_n)) / sin γ (or the engines' rule,
// LispsmNearRule), and whose depth spans the body along f; the map is that frustum's (x, depth)
// seen along l. The world map is warp · light view. Point lights go "through the light's
// perspective first" (Wimmer et al.): the normal light frustum H maps the light to infinity along
// +z, so in H's space the light is directional and the same construction applies to H(eye), the
// view direction pushed through H's Jacobian at the eye, and H(B); the world map is warp · H.
//
// PSM (Stamminger & Drettakis 2002; Kozlov, GPU Gems ch. 14). In the post-perspective space (NDC)
// of the camera C, the light L becomes the homogeneous point C·L = (ℓ, ℓw): a point light a point
// (or a direction when it lies on the camera plane, ℓw = 0), a directional light a point. The
// light's frustum in NDC has axis a, that of the narrowest cone from the light around the NDC body
// (as PSM fits the light frustum around the transformed body), and rows
//     row_i = (ℓw r_i, -r_i·ℓ), row_4 = (ℓw a, -a·ℓ)     (r_1, r_2 ⊥ a),
// so that row·[p, 1] = r·(ℓw p - ℓ): this annihilates C·L for every sign of ℓw. For ℓw > 0 it is
// the usual frustum from the NDC light point ℓ/ℓw; for ℓw → 0 it tends continuously to the
// orthographic map along ℓ; for ℓw < 0 (a light behind the viewer) the rows change sign relative to
// the usual frustum, which is exactly Kozlov's inverted projection (the light sees the unit cube
// "through infinity", near and far swapped). The camera is first slid back (Kozlov's virtual
// camera) by PsmSlideBack so that the virtual near/far ratio is at least kPsmMinNearFarRatio.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "lexel/spatial/baseline_support.h"
#include "lexel/spatial/baselines.h"

namespace lexel::spatial {

using namespace baseline_detail;

namespace {

// Below this |sin γ| (dimensionless; γ within ~0.06° of 0 or 180°) the view direction has no
// component across the light and LiSPSM's frustum cannot be oriented; the warping methods revert
// to the unwarped map there (Lloyd 2006 §4.4: "PSMs, LSPSMs, and TSMs all revert back to an
// orthogonal projection"), which n_opt → ∞ approaches continuously anyway. Ours is focused.
constexpr double kLispsmMinSinGamma = 1e-3;

void Note(BaselineDiagnostics* diagnostics, const std::string& why) {
    if (diagnostics == nullptr) return;
    if (!diagnostics->fallback.empty()) diagnostics->fallback += "; ";
    diagnostics->fallback += why;
}

glm::dvec3 Centroid(const std::vector<glm::dvec3>& points) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : points) sum += p;
    return sum / static_cast<double>(points.size());
}

// What both warps start from: the checked context, the normal axis and the focus body, and their
// fallback to the focused map with the reason noted.
struct WarpStart {
    WarpStart(const BaselineContext& context, BaselineDiagnostics* diagnostics, const char* method)
        : context(context), diagnostics(diagnostics), method(method) {
        CheckContext(context);
        axis = ChooseNormalAxis(context);
        wsBody = FocusBody(context, axis);
    }
    LightMatrix FallBack(const std::string& why) const {
        Note(diagnostics, std::string(method) + ": " + why + "; using focused");
        return FocusedLightMatrix(context, diagnostics);
    }
    const BaselineContext& context;
    BaselineDiagnostics* diagnostics;
    const char* method;
    NormalAxis axis;
    std::vector<glm::dvec3> wsBody;
};

// Keeps the warp's p4, refits the affine part over the body and checks the relevant points.
std::optional<LightMatrix> RefitOverBody(const BaselineContext& context, const glm::dvec3& p4,
                                         const std::vector<glm::dvec3>& wsBody) {
    const LightSpace& ls = *context.lightSpace;
    const auto m = FitMapToPoints(p4, ToLightAll(ls, wsBody), context.map);
    if (!m || !CoversAll(*m, ToLightAll(ls, context.wsRelevant), context.map)) return std::nullopt;
    return m;
}

// A tight warp's map: the warp's own axes, scaled and shifted so that the visible points' bounds
// (grown by the context's margin) fill the map; focused-tight where the warp failed.
LightMatrix FitTight(const BaselineContext& context, const std::optional<LightMatrix>& warped,
                     const char* method, const std::string& failure,
                     BaselineDiagnostics* diagnostics) {
    std::string why = failure;
    if (warped) {
        const auto m =
            ScaleMapToCover(*warped, RelevantLight(context), context.map, context.margin);
        if (m && CoversAll(*m, RelevantLight(context), context.map)) return *m;
        why = "the warp leaves a visible point behind its plane";
    }
    Note(diagnostics, std::string(method) + ": " + why + "; using focused-tight");
    return FocusedTightLightMatrix(context, diagnostics);
}

// Body depths along the unit view direction from the eye: [min, max] over the body.
void DepthRange(std::span<const glm::dvec3> body, const glm::dvec3& eye, const glm::dvec3& view,
                double* zNear, double* zFar) {
    *zNear = std::numeric_limits<double>::infinity();
    *zFar = -std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p : body) {
        const double z = glm::dot(p - eye, view);
        *zNear = std::min(*zNear, z);
        *zFar = std::max(*zFar, z);
    }
}

// LiSPSM's warp for a body (the header comment): the light matrix whose rows are the warp's own
// map axes (frustum x, frustum depth) and whose p4 is its optical axis; nullopt, with the reason
// in *failure, where the construction degenerates. The frustum holds wsBody; n comes from `rule`
// with the depths z_n, z_f of wsDepthBody along the view direction (the body itself for the
// report's LiSPSM, the visible points for the tight ones, whose body reaches toward the light and
// may pass behind the eye) and wsBody's extent d along the warp axis.
std::optional<LightMatrix> LispsmWarp(const BaselineContext& context, const NormalAxis& axis,
                                      const std::vector<glm::dvec3>& wsBody,
                                      std::span<const glm::dvec3> wsDepthBody,
                                      const LispsmNearRule& rule, BaselineDiagnostics* diagnostics,
                                      std::string* failure) {
    const auto fail = [&](const std::string& why) -> std::optional<LightMatrix> {
        *failure = why;
        return std::nullopt;
    };
    if (wsBody.empty()) return fail("empty focus body");
    const LightSpace& ls = *context.lightSpace;
    const Camera& camera = context.camera;
    // H: world → the space where the light travels along +z (rows act on [x; 1]).
    glm::dmat4 dFromWorld;
    if (ls.IsPoint()) {
        // The normal light frustum about the normal axis p4 (world g3; g1, g2 ⊥ it), with depth
        // w = g3·(x - L):  x_D = w0 g1·(x - L) / w,  y_D = w0 g2·(x - L) / w,  z_D = -w0² / w.
        // H·[L, 1] = (0, 0, -w0², 0): the light is at infinity toward -z and its rays travel
        // toward +z. w0 = the eye's depth makes H a rigid motion to first order at the eye, so
        // γ there is the world angle between the view direction and the light ray through the
        // eye, and the construction tends to the directional one as the light recedes. (Any other
        // scale of z_D would change γ: post-perspective angles are not invariant.)
        glm::dvec3 b1, b2;
        PlaneBasis(axis.p4, &b1, &b2);
        const glm::dmat3 wsFromLs = glm::transpose(ls.LsFromWsLinear());
        const glm::dvec3 g1 = wsFromLs * b1, g2 = wsFromLs * b2;
        const glm::dvec3 g3 = wsFromLs * axis.p4, wsLight = ls.light().position;
        for (const glm::dvec3& x : wsBody)
            if (!(glm::dot(g3, x - wsLight) > 0.0))
                return fail("the body reaches the light's plane");
        const double w0 = glm::dot(g3, camera.position - wsLight);
        if (!(w0 > 0.0)) return fail("the eye is behind the light's plane");
        dFromWorld =
            FromRows(glm::dvec4(w0 * g1, -w0 * glm::dot(g1, wsLight)),
                     glm::dvec4(w0 * g2, -w0 * glm::dot(g2, wsLight)),
                     glm::dvec4(0.0, 0.0, 0.0, -w0 * w0), glm::dvec4(g3, -glm::dot(g3, wsLight)));
    } else {
        // A rigid light view: distances (and so z_n, z_f, n_opt) stay in world units.
        const glm::dmat3 wsFromLs = glm::transpose(ls.LsFromWsLinear());
        const glm::dvec3 e1 = wsFromLs[0], e2 = wsFromLs[1];  // ⊥ the light
        const glm::dvec3 l = ls.light().direction, o = context.wsBounds.Center();
        dFromWorld = FromRows(glm::dvec4(e1, -glm::dot(e1, o)), glm::dvec4(e2, -glm::dot(e2, o)),
                              glm::dvec4(l, -glm::dot(l, o)), glm::dvec4(0.0, 0.0, 0.0, 1.0));
    }
    auto toD = [&](const glm::dvec3& x, bool* ok) {
        const glm::dvec4 h = dFromWorld * glm::dvec4(x, 1.0);
        if (!(h.w > 0.0)) *ok = false;
        return glm::dvec3(h) / h.w;
    };
    bool ok = true;
    const glm::dvec3 eyeD = toD(camera.position, &ok);
    if (!ok) return fail("the eye is behind the light's plane");
    std::vector<glm::dvec3> bodyD;
    for (const glm::dvec3& x : wsBody) bodyD.push_back(toD(x, &ok));
    if (!ok) return fail("a body point is behind the light's plane");
    // The view direction through H's Jacobian at the eye: d/dt of dehom(H [eye + t v; 1]).
    const glm::dvec3 wsView = glm::normalize(camera.target - camera.position);
    const glm::dvec4 hEye = dFromWorld * glm::dvec4(camera.position, 1.0);
    const glm::dvec4 hView = dFromWorld * glm::dvec4(wsView, 0.0);
    const glm::dvec3 viewD = glm::normalize(
        (glm::dvec3(hView) * hEye.w - glm::dvec3(hEye) * hView.w) / (hEye.w * hEye.w));

    // γ: the angle between the view direction and the light direction (+z here).
    const double sinGamma = std::hypot(viewD.x, viewD.y);
    if (diagnostics) diagnostics->sinGamma = sinGamma;
    if (!(sinGamma >= kLispsmMinSinGamma))
        return fail("view direction within ~0.06° of the light direction");
    const glm::dvec3 axisF(viewD.x / sinGamma, viewD.y / sinGamma, 0.0);  // projected view dir

    std::vector<glm::dvec3> depthBodyD;
    for (const glm::dvec3& x : wsDepthBody) depthBodyD.push_back(toD(x, &ok));
    if (!ok) return fail("a body point is behind the light's plane");
    double zNear, zFar;
    DepthRange(depthBodyD, eyeD, viewD, &zNear, &zFar);
    if (!(zFar > 0.0)) return fail("the body is behind the eye");
    // The camera's near plane clamped to the body: the body lies inside the view frustum, so for a
    // directional light (rigid H) zNear ≥ camera.nearPlane already; the 1e-6 floor (relative to
    // z_f) only keeps n_opt > 0 where H bends the depths of a point light's body.
    zNear = std::max(zNear, 1e-6 * zFar);
    double fMin = std::numeric_limits<double>::infinity();
    double fMax = -std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p : bodyD) {
        fMin = std::min(fMin, glm::dot(axisF, p));
        fMax = std::max(fMax, glm::dot(axisF, p));
    }
    if (diagnostics) {
        diagnostics->zNear = zNear;
        diagnostics->zFar = zFar;
        diagnostics->warpDepth = fMax - fMin;
    }
    const std::optional<double> nRule =
        LispsmNear(rule, {zNear, zFar, fMax - fMin}, sinGamma, camera.nearPlane);
    if (!nRule)
        return fail(
            "no n: the virtual near plane lies beyond 2/3 of the depth range, or the depths "
            "degenerate");
    const double nOpt = *nRule;
    if (diagnostics) diagnostics->nOpt = nOpt;
    // Projection centre: at the eye across f, n_opt before the body's near face along f.
    const glm::dvec3 center = eyeD + (fMin - nOpt - glm::dot(axisF, eyeD)) * axisF;
    const double nearW = nOpt, farW = nOpt + std::max(fMax - fMin, 1e-9 * nOpt);
    const double depthA = (farW + nearW) / (farW - nearW);
    const double depthB = -2.0 * farW * nearW / (farW - nearW);
    const glm::dvec3 right = glm::cross(axisF, glm::dvec3(0.0, 0.0, 1.0));  // unit, ⊥ light
    const glm::dvec3 lightAxis(0.0, 0.0, 1.0);
    // Map rows: (frustum x, frustum depth, [light depth, ignored], w = f·(p - c)); the light
    // direction +z is dropped, so every row but the ignored one annihilates it.
    const glm::dmat4 warp =
        FromRows(glm::dvec4(right, -glm::dot(right, center)),
                 glm::dvec4(depthA * axisF, -depthA * glm::dot(axisF, center) + depthB),
                 glm::dvec4(lightAxis, -glm::dot(lightAxis, center)),
                 glm::dvec4(axisF, -glm::dot(axisF, center)));
    std::string rowsFailure;
    const std::optional<LightMatrix> warped =
        FromScreenRows(ls, warp * dFromWorld, Centroid(wsBody), &rowsFailure);
    if (!warped) return fail("light matrix: " + rowsFailure);
    return warped;
}

// PSM's light frustum in the camera's post-perspective space for a body (the header comment), as
// a light matrix whose rows are that frustum's map axes; nullopt, with the reason in *failure.
std::optional<LightMatrix> PsmWarp(const BaselineContext& context,
                                   const std::vector<glm::dvec3>& wsBody,
                                   BaselineDiagnostics* diagnostics, std::string* failure) {
    const auto fail = [&](const std::string& why) -> std::optional<LightMatrix> {
        *failure = why;
        return std::nullopt;
    };
    if (wsBody.empty()) return fail("empty focus body");
    const LightSpace& ls = *context.lightSpace;
    const Camera& camera = context.camera;
    const glm::dvec3 wsView = glm::normalize(camera.target - camera.position);
    double zNear, zFar;
    DepthRange(wsBody, camera.position, wsView, &zNear, &zFar);
    if (!(zFar > 0.0)) return fail("the body is behind the eye");
    // The report's body lies in the view frustum, so zNear ≥ camera.nearPlane up to rounding.
    // A tight body swept toward a light behind the viewer reaches behind the eye (zNear ≤ 0):
    // the slide back then moves the virtual camera behind it (Kozlov's virtual camera).
    if (zNear > 0.0) zNear = std::max(zNear, 0.5 * camera.nearPlane);
    zFar = std::max(zFar, zNear * (1.0 + 1e-9));
    const double slideBack = PsmSlideBack(zNear, zFar);
    const Camera virtualCamera = PsmVirtualCamera(camera, zNear, zFar, slideBack);
    const glm::dmat4 clipFromWorld = virtualCamera.ClipFromView() * virtualCamera.ViewFromWorld();
    // A directional light travelling along l sits at infinity toward -l.
    const glm::dvec4 wsLight = ls.IsPoint() ? glm::dvec4(ls.light().position, 1.0)
                                            : glm::dvec4(-ls.light().direction, 0.0);
    const glm::dvec4 clipLight = clipFromWorld * wsLight;
    if (diagnostics) {
        diagnostics->clipLight = clipLight;
        diagnostics->slideBack = slideBack;
        diagnostics->zNear = zNear;
        diagnostics->zFar = zFar;
    }
    const glm::dvec3 ell(clipLight);
    const double ellW = clipLight.w;

    std::vector<glm::dvec3> ppsBody;
    for (const glm::dvec3& x : wsBody) {
        const glm::dvec4 h = clipFromWorld * glm::dvec4(x, 1.0);
        if (!(h.w > 0.0)) return fail("a body point is behind the virtual camera");
        ppsBody.push_back(glm::dvec3(h) / h.w);
    }
    // The directions ℓw p - ℓ from the light to the NDC body (sign included: for ℓw < 0 they point
    // "through infinity"); the light frustum's axis a is that of the narrowest cone around them.
    std::vector<glm::dvec3> directions;
    for (const glm::dvec3& p : ppsBody) {
        const glm::dvec3 d = ellW * p - ell;
        const double len = glm::length(d);
        if (!(len > 0.0)) return fail("the light sits on the NDC body");
        directions.push_back(d / len);
    }
    const auto axisA = NarrowestConeAxis(directions);
    if (!axisA) return fail("no light frustum in NDC holds the whole body");
    const glm::dvec3 a = *axisA;
    glm::dvec3 ppsInside(0.0);  // a body point with a·(ℓw p - ℓ) > 0, to orient p4 below
    double best = -1.0;
    for (std::size_t i = 0; i < ppsBody.size(); ++i)
        if (glm::dot(a, directions[i]) > best) {
            best = glm::dot(a, directions[i]);
            ppsInside = ppsBody[i];
        }
    glm::dvec3 r1, r2;
    PlaneBasis(a, &r1, &r2);
    const glm::dmat4 lightFromPps = FromRows(
        glm::dvec4(ellW * r1, -glm::dot(r1, ell)), glm::dvec4(ellW * r2, -glm::dot(r2, ell)),
        glm::dvec4(0.0), glm::dvec4(ellW * a, -glm::dot(a, ell)));
    // Row 4 is positive at ppsInside; hand FromScreenRows that point's world preimage so that it
    // orients p4 the same way.
    const glm::dvec4 wsInsideH = glm::inverse(clipFromWorld) * glm::dvec4(ppsInside, 1.0);
    if (!(std::abs(wsInsideH.w) > 0.0)) return fail("degenerate NDC body point");
    std::string rowsFailure;
    const std::optional<LightMatrix> warped = FromScreenRows(
        ls, lightFromPps * clipFromWorld, glm::dvec3(wsInsideH) / wsInsideH.w, &rowsFailure);
    if (!warped) return fail("light matrix: " + rowsFailure);
    return warped;
}

}  // namespace

double LispsmOptimalNear(double zNear, double zFar, double sinGamma) {
    return (zNear + std::sqrt(zFar * zNear)) / sinGamma;
}

std::optional<double> LispsmNear(const LispsmNearRule& rule, const LispsmDepths& depths,
                                 double sinGamma, double cameraNear) {
    const double zn = depths.zNear, zf = depths.zFar, d = depths.warpDepth;
    if (!(sinGamma > 0.0 && zn > 0.0 && zf >= zn && d >= 0.0 && std::isfinite(zf) &&
          std::isfinite(d)))
        return std::nullopt;
    if (rule.kind == LispsmNearRule::Kind::kWimmer) return LispsmOptimalNear(zn, zf, sinGamma);
    if (rule.kind == LispsmNearRule::Kind::kNearDepth) return zn / sinGamma;
    // ShadowMap::applyLISPSM's names: z0, z1 the near and far depth along the warp axis, dzn how
    // far the virtual near plane lies beyond the camera's (world units).
    const double z0 = zn, z1 = z0 + d * sinGamma;
    const double dzn = std::max(0.0, rule.virtualNear - cameraNear);
    const double vz0 = dzn > 0.0 ? std::max(z0, rule.virtualNear) : z0;
    const double vz1 = std::max(0.0, std::min({z1, zf, rule.virtualFar}));
    const double nOpt0 = (z0 + std::sqrt(vz0 * vz1)) / sinGamma;
    if (dzn == 0.0) return nOpt0;
    // Filament: with the near plane pushed that far, the largest error leaves the depth range and
    // n must be at least nOpt1; at 2/3 of the range nOpt1 is infinite (the orthographic map).
    if (!(3.0 * dzn < 2.0 * (zf - zn))) return std::nullopt;
    const double nOpt1 = dzn / (2.0 - 3.0 * dzn / (zf - zn));
    return std::max(nOpt0, nOpt1);
}

double PsmSlideBack(double zNear, double zFar) {
    const double rho = kPsmMinNearFarRatio;
    return std::max(0.0, (rho * zFar - zNear) / (1.0 - rho));
}

Camera PsmVirtualCamera(const Camera& camera, double zNear, double zFar, double slideBack) {
    Camera virtualCamera = camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    virtualCamera.position -= slideBack * forward;
    virtualCamera.target -= slideBack * forward;
    virtualCamera.nearPlane = zNear + slideBack;
    virtualCamera.farPlane = zFar + slideBack;
    return virtualCamera;
}

LightMatrix LispsmLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    const WarpStart start(context, diagnostics, "lispsm");
    std::string failure;
    const std::optional<LightMatrix> warped =
        LispsmWarp(context, start.axis, start.wsBody, start.wsBody, {}, diagnostics, &failure);
    if (!warped) return start.FallBack(failure);
    const auto m = RefitOverBody(context, warped->p4, start.wsBody);
    if (!m)
        return start.FallBack("the warp's p4 leaves a body or relevant point behind or outside");
    return *m;
}

LightMatrix PsmLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    const WarpStart start(context, diagnostics, "psm");
    std::string failure;
    const std::optional<LightMatrix> warped = PsmWarp(context, start.wsBody, diagnostics, &failure);
    if (!warped) return start.FallBack(failure);
    const auto m = RefitOverBody(context, warped->p4, start.wsBody);
    if (!m) return start.FallBack("the NDC light frustum leaves a body or relevant point behind");
    return *m;
}

LightMatrix LispsmRuleLightMatrix(const BaselineContext& context, const LispsmNearRule& rule,
                                  BaselineDiagnostics* diagnostics) {
    CheckContext(context);
    std::string failure;
    const std::optional<LightMatrix> warped =
        LispsmWarp(context, ChooseNormalAxis(context), TightBody(context),
                   context.wsRelevantHull.empty() ? context.wsRelevant : context.wsRelevantHull,
                   rule, diagnostics, &failure);
    const char* method = rule.kind == LispsmNearRule::Kind::kWimmer   ? "lispsm-tight"
                         : rule.kind == LispsmNearRule::Kind::kEngine ? "lispsm-engine"
                                                                      : "logpsm";
    return FitTight(context, warped, method, failure, diagnostics);
}

LightMatrix LispsmTightLightMatrix(const BaselineContext& context,
                                   BaselineDiagnostics* diagnostics) {
    return LispsmRuleLightMatrix(context, {}, diagnostics);
}

LightMatrix LispsmEngineLightMatrix(const BaselineContext& context,
                                    BaselineDiagnostics* diagnostics) {
    return LispsmRuleLightMatrix(context, {LispsmNearRule::Kind::kEngine}, diagnostics);
}

LightMatrix PsmTightLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    CheckContext(context);
    std::string failure;
    const std::optional<LightMatrix> warped =
        PsmWarp(context, TightBody(context), diagnostics, &failure);
    return FitTight(context, warped, "psm-tight", failure, diagnostics);
}

}  // namespace lexel::spatial
