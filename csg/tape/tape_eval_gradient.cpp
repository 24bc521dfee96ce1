// Point evaluation with the gradient: forward-mode dual numbers, one value and one
// ∂/∂(x, y, z) per slot, in per-thread scratch.
#include "csg/interval/interval_trig.h"
#include "csg/interval/scalar_ops.h"
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

inline bool isZero(const Vec3& g) { return g == Vec3(0.0); }
inline bool isZero(double g) { return g == 0.0; }

/// The derivative rules; the value itself comes from applyScalarOp, so eval() and
/// evalGradient() return the same f bit for bit.
template <typename G>
G derivative(Op op, const Dual<G>& a, const Dual<G>& b, double value, double result) {
    switch (op) {
        case Op::Neg: return -a.g;
        case Op::Square: return (2.0 * a.v) * a.g;
        case Op::Sqrt: return a.g / (2.0 * result);
        case Op::Abs: return a.v < 0.0 ? -a.g : a.g;
        case Op::Sin: return std::cos(a.v) * a.g;
        case Op::Cos: return -std::sin(a.v) * a.g;
        case Op::Tan: return (1.0 + result * result) * a.g;
        case Op::Asin: return a.g / std::sqrt(1.0 - a.v * a.v);
        case Op::Acos: return -a.g / std::sqrt(1.0 - a.v * a.v);
        case Op::Atan: return a.g / (1.0 + a.v * a.v);
        case Op::Exp: return result * a.g;
        case Op::Log: return a.g / a.v;
        case Op::Floor:
        case Op::Ceil: return G(0.0);  // piecewise constant
        case Op::Add: return a.g + b.g;
        case Op::Sub: return a.g - b.g;
        case Op::Mul: return b.v * a.g + a.v * b.g;
        case Op::Div: return (a.g - result * b.g) / b.v;
        case Op::Pow: {
            // d(aᵇ) = b·aᵇ⁻¹·da + aᵇ·ln a·db; the second term only when b varies, so that a
            // constant exponent at a = 0 does not bring in 0·ln 0.
            G g = (b.v * std::pow(a.v, b.v - 1.0)) * a.g;
            if (!isZero(b.g)) g += (result * std::log(a.v)) * b.g;
            return g;
        }
        case Op::Atan2: return (b.v * a.g - a.v * b.g) / (a.v * a.v + b.v * b.v);
        case Op::Min: return a.v <= b.v ? a.g : b.g;
        case Op::Max: return a.v >= b.v ? a.g : b.g;
        case Op::PowInt: {
            const int n = static_cast<int>(value);
            return n == 0 ? G(0.0) : (value * std::pow(a.v, n - 1)) * a.g;
        }
        default: return G(0.0);
    }
}

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
                s[i] = in.op == Op::Sin ? Dual<G>{sv, cv * a.g} : Dual<G>{cv, -sv * a.g};
                break;
            }
            case Op::Noise: {  // the chain rule through the noise's own gradient
                const Dual<G>&a = s[in.a], &b = s[in.b], &c = s[in.c];
                Vec3 n;
                const double v = gradientNoise(Vec3(a.v, b.v, c.v), noiseSeed(in), n);
                s[i] = {v, n.x * a.g + n.y * b.g + n.z * c.g};
                break;
            }
            case Op::Field: {  // the same chain rule through the field's gradient
                const Dual<G>&a = s[in.a], &b = s[in.b], &c = s[in.c];
                Vec3 n;
                const double v = tape.field(in).valueGradient(Vec3(a.v, b.v, c.v), n);
                s[i] = {v, n.x * a.g + n.y * b.g + n.z * c.g};
                break;
            }
            default: {
                const Dual<G>& a = s[in.a];
                const Dual<G>& b = in.b >= 0 ? s[in.b] : none;
                const double v = applyScalarOp(in.op, a.v, b.v, in.value);
                s[i] = {v, derivative(in.op, a, b, in.value, v)};
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
