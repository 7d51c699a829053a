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
