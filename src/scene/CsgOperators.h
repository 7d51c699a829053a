#pragma once
// The CSG operators, each described once in SCENE_CSG_OPERATORS: its words in the scene
// format, its GLSL function (shaders/modules/csg_operators.glsl), which solid it builds and
// how it is smoothed. The enum, the parser's words, the shaders' codes (CSG_<KIND>, as
// generated #defines), the generated calls, the interpreter's switch and the bounds all come
// from this list (an X-macro, as LLVM lists its instructions in Instruction.def).
//
// Adding an operator: a row here and its function in csg_operators.glsl (and, for a new
// smoothing, its margin in scene/SceneBounds.cpp). tests/scene/KindTablesTest.cpp walks
// every row.
#include <string>
#include <vector>

namespace scene {

// The solid an operator builds from its operands (the first minus all others for a
// difference).
enum class CsgCombination { Union, Intersection, Difference };

// How an operator rounds the edges where its operands meet, and what its parameter means.
enum class CsgSmoothing {
    Sharp,        // no parameter
    Exponential,  // the seed's smooth minimum; parameter: sharpness k > 0
    Polynomial,   // Quilez's quadratic smooth minimum; parameter: blend radius >= 0
};

//  X(kind, keyword, smoothing word or "", GLSL function, combination, smoothing), in code order
#define SCENE_CSG_OPERATORS(X)                                                                     \
    X(Union, "union", "", "opUnion", Union, Sharp)                                                 \
    X(Intersection, "intersection", "", "opIntersection", Intersection, Sharp)                     \
    X(Difference, "difference", "", "opDifference", Difference, Sharp)                             \
    X(SmoothUnion, "smooth_union", "exp", "opSmoothUnionExp", Union, Exponential)                  \
    X(SmoothIntersection, "smooth_intersection", "exp", "opSmoothIntersectionExp", Intersection,   \
      Exponential)                                                                                 \
    X(SmoothDifference, "smooth_difference", "exp", "opSmoothDifferenceExp", Difference,           \
      Exponential)                                                                                 \
    X(PolynomialSmoothUnion, "smooth_union", "poly", "opSmoothUnionPoly", Union, Polynomial)       \
    X(PolynomialSmoothIntersection, "smooth_intersection", "poly", "opSmoothIntersectionPoly",     \
      Intersection, Polynomial)                                                                    \
    X(PolynomialSmoothDifference, "smooth_difference", "poly", "opSmoothDifferencePoly",           \
      Difference, Polynomial)

enum class CsgOperator {
#define SCENE_CSG_ENUMERATOR(kind, ...) kind,
    SCENE_CSG_OPERATORS(SCENE_CSG_ENUMERATOR)
#undef SCENE_CSG_ENUMERATOR
};

struct CsgOperatorDescription {
    CsgOperator op;
    int code;                // its place in the list; the shaders' CSG_<IDENTIFIER>
    const char* identifier;  // the enumerator's name
    const char* keyword;
    const char* smoothingWord;  // the word after the keyword, "" for a sharp operator
    const char* function;       // GLSL: float f(float a, float b) or f(a, b, parameter)
    CsgCombination combination;
    CsgSmoothing smoothing;

    bool hasParameter() const { return smoothing != CsgSmoothing::Sharp; }
};

// Every operator, in code order.
const std::vector<CsgOperatorDescription>& csgOperatorDescriptions();
const CsgOperatorDescription& describe(CsgOperator op);
// The operator a keyword and a smoothing word ("" after a sharp one) name, or nullptr.
const CsgOperatorDescription* findCsgOperator(const std::string& keyword,
                                              const std::string& smoothingWord);
// A keyword that opens a CSG block: every operator's.
bool isCsgKeyword(const std::string& word);
// The shaders' name for an operator's code: CSG_ and the identifier in capitals.
std::string codeName(const CsgOperatorDescription& description);

}  // namespace scene
