// The command-line names of the trace methods.
#include "csg/trace_context.h"

namespace kerf {

const char* traceMethodName(TraceMethod method) {
    switch (method) {
        case TraceMethod::Closed: return "closed";
        case TraceMethod::Interval: return "interval";
        case TraceMethod::SphereTrace: return "sphere-trace";
    }
    return "?";
}

std::optional<TraceMethod> parseTraceMethod(const std::string& name) {
    for (TraceMethod m : {TraceMethod::Closed, TraceMethod::Interval, TraceMethod::SphereTrace})
        if (name == traceMethodName(m)) return m;
    return std::nullopt;
}

}  // namespace kerf
