/// @file csg/tree/motion.h
/// @brief Motion blur's clock: the scene time of the sample a thread is tracing. Moving solids
/// (makeMotion, csg/tree/solids.h) are placed where they are at that time; their bounds and
/// interval values hold for the whole of it, so acceleration structures built once stay sound.
#pragma once

namespace kerf {

/// The scene time, in [0, 1], of the sample this thread traces (0 unless a scope sets it).
double sceneTime();

/// Sets this thread's scene time for its lifetime (and restores the previous one after).
class SceneTimeScope {
public:
    explicit SceneTimeScope(double time);
    ~SceneTimeScope();
    SceneTimeScope(const SceneTimeScope&) = delete;
    SceneTimeScope& operator=(const SceneTimeScope&) = delete;

private:
    double mPrevious;
};

}  // namespace kerf
