// Point evaluation with the gradient: forward-mode dual numbers, one value and one
// ∂/∂(x, y, z) per slot, in per-thread scratch.
#include "csg/interval/interval_trig.h"
#include "csg/interval/scalar_ops.h"
#include "csg/tape/derivative_rules.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"

namespace kerf {
namespace {

/// A value and its derivative: the gradient (G = Vec3) or the slope along a ray (G = double).
template <typename G>
struct Dual {
    double v;
    G g;
};

/// Forward-mode evaluation at p with the inputs' derivatives dx, dy, dz: the gradient when
/// they are the unit vectors, the slope along a ray when they are its direction's components.
/// The values are those of Tape::eval(p), bit for bit (the same operations in the same order).
template <typename G>
Dual<G> evalDual(const Tape& tape, const Vec3& p, const G& dx, const G& dy, const G& dz) {
    const std::vector<TapeInstr>& instrs = tape.instrs();
    thread_local std::vector<Dual<G>> slots;
    slots.resize(instrs.size());
    Dual<G>* s = slots.data();
    const Dual<G> none{0.0, G(0.0)};
    for (size_t i = 0; i < instrs.size(); ++i) {
        const TapeInstr& in = instrs[i];
        switch (in.op) {
            case Op::Const: s[i] = {in.value, G(0.0)}; break;
            case Op::VarX: s[i] = {p.x, dx}; break;
            case Op::VarY: s[i] = {p.y, dy}; break;
            case Op::VarZ: s[i] = {p.z, dz}; break;
            case Op::Sin:
            case Op::Cos: {  // one reduction for the value and the slope, as Tape::eval
                const Dual<G>& a = s[in.a];
                double sv, cv;
                interval_trig::pointSinCos(a.v, sv, cv);
                s[i] = in.op == Op::Sin ? Dual<G>{sv, derivative_rules::sinSlope(cv, a.g)}
                                        : Dual<G>{cv, derivative_rules::cosSlope(sv, a.g)};
                break;
            }
            case Op::Noise: {  // the chain rule through the noise's own gradient
                const Dual<G>&a = s[in.a], &b = s[in.b], &c = s[in.c];
                Vec3 n;
                const double v = gradientNoise(Vec3(a.v, b.v, c.v), noiseSeed(in), n);
                const double g[3] = {n.x, n.y, n.z};
                s[i] = {v, derivative_rules::chainSlope(g, a.g, b.g, c.g)};
                break;
            }
            case Op::Field: {  // the same chain rule through the field's gradient
                const Dual<G>&a = s[in.a], &b = s[in.b], &c = s[in.c];
                Vec3 n;
                const double v = tape.field(in).valueGradient(Vec3(a.v, b.v, c.v), n);
                const double g[3] = {n.x, n.y, n.z};
                s[i] = {v, derivative_rules::chainSlope(g, a.g, b.g, c.g)};
                break;
            }
            default: {
                const Dual<G>& a = s[in.a];
                const Dual<G>& b = in.b >= 0 ? s[in.b] : none;
                const double v = applyScalarOp(in.op, a.v, b.v, in.value);
                s[i] = {v, derivative_rules::derivative(in.op, a.v, a.g, b.v, b.g, in.value, v)};
            }
        }
    }
    return s[instrs.size() - 1];
}

}  // namespace

double Tape::evalGradient(const Vec3& p, Vec3& gradient) const {
    const Dual<Vec3> r =
        evalDual(*this, p, Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0, 0.0, 1.0));
    gradient = r.g;
    return r.v;
}

double Tape::evalAlongRay(const Ray& ray, double t, double& dfdt) const {
    const Dual<double> r = evalDual(*this, ray.at(t), ray.dir.x, ray.dir.y, ray.dir.z);
    dfdt = r.g;
    return r.v;
}

}  // namespace kerf
