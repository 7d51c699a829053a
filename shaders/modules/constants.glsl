// Numeric constants shared by every module.

const float PI = 3.14159265358979323846;
const float TWO_PI = 6.28318530717958647692;
const float INV_PI = 0.31830988618379067154;
const float INV_TWO_PI = 0.15915494309189533577;
const float FLOAT_MAX = 3.402823e38;

float maxComponent(vec3 v)
{
    return max(v.x, max(v.y, v.z));
}

float averageComponent(vec3 v)
{
    return (v.x + v.y + v.z) * (1.0 / 3.0);
}

// Mesa's llvmpipe ends every loop of a shader invocation once the iterations of all its loops
// together reach 65535 (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, a guard against hangs): a
// pixel that traces many paths in one frame would see its last path cut short, its march
// ending as a miss, and that wrong sample averaged in. So every loop of the path tracer
// counts its iterations against a budget below that limit, and a path still unfinished when
// the budget is spent is abandoned, neither kept nor counted: its sample index is traced
// again, whole, in the next frame (path_tracer_main.glsl). Only loops of at most four
// iterations go uncounted; the margin covers them.
const int kLoopIterationBudget = 60000;
int loopIterationsLeft = kLoopIterationBudget;

// Counts one iteration; false once the budget is spent, which ends every counted loop.
bool loopIterationAllowed()
{
    return --loopIterationsLeft >= 0;
}

bool loopBudgetSpent()
{
    return loopIterationsLeft < 0;
}
