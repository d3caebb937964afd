// pavement's layouts as data: each one a periodic table of tile letters over its cells, the
// one list both the interp (what is modelled; the rest is reported unsupported) and the
// renderer (render/patterns/pavement.cpp) read. A cell's walls and corners are derived from its
// neighbours: cells of different letters lie in different tiles, so two tiles of one letter
// never touch, not even at a corner. Read off POV-Ray 3.7's 16-bit renders of the pattern.
#pragma once
#include <string_view>

namespace lumen::scene {

struct PavementLayout {
    int sides, tiles, number;  // number_of_sides, number_of_tiles, pattern
    int width, height;         // the period, in cells along x and z
    std::string_view cells;    // height rows of width letters, the row at z = 0 first

    // The letter of cell (column, row), the table repeating in both directions.
    constexpr char at(long column, long row) const {
        const long c = ((column % width) + width) % width, r = ((row % height) + height) % height;
        return cells[std::size_t(r * width + c)];
    }
};

// Square cells (number_of_sides 4), every layout of 1-6 tiles: 1 the single squares, 2 POV's
// dominoes (upright along z), then the trominoes, tetrominoes, pentominoes and hexominoes in
// POV's order. Each table was read off POV's walls over a 48 x 48 cell render, its period the
// smallest rectangle that repeats them (doubled where one letter would touch itself).
// clang-format off
inline constexpr PavementLayout kPavementLayouts[] = {
    {4, 1, 1, 2, 2, "BA" "DC"},
    {4, 2, 1, 2, 4, "BA" "BA" "DC" "DC"},
    {4, 3, 1, 6, 2, "BBBAAA" "DDDCCC"},
    {4, 3, 2, 3, 4, "BAA" "BBA" "DCC" "DDC"},
    {4, 4, 1, 8, 2, "BBBBAAAA" "DDDDCCCC"},
    {4, 4, 2, 4, 4, "BAAA" "BBBA" "DCCC" "DDDC"},
    {4, 4, 3, 4, 4, "BBBA" "CBCC" "DDDC" "ADAA"},
    {4, 4, 4, 4, 4, "BBAA" "BBAA" "DDCC" "DDCC"},
    {4, 4, 5, 4, 4, "ABBA" "BBAA" "DDCC" "DCCD"},
    {4, 5, 1, 10, 2, "BBBBBAAAAA" "DDDDDCCCCC"},
    {4, 5, 2, 5, 4, "BAAAA" "BBBBA" "DCCCC" "DDDDC"},
    {4, 5, 3, 5, 10, "BAABB" "AAABB" "CCCDD" "CCDDD" "FFEEE" "FFEEF" "HHGGH" "HGGGH" "JIIIJ"
      "JIIJJ"},
    {4, 5, 4, 5, 5, "AAAAB" "CCACC" "CDDDD" "EEEDE" "BEBBB"},
    {4, 5, 5, 5, 5, "AAACB" "BADBB" "EDDDB" "EEDCE" "EACCC"},
    {4, 5, 6, 10, 10, "DCBBBAAAFE" "DCCCGGGAFH" "DDDIIIGAJH" "HHLLLIGKJH" "JNNNLIMKJJ"
      "PPPNLOMKKK" "RRPNQOMMMR" "TRPSQOOOTT" "TRBSQQQEEE" "TCBSSSFFFE"},
    {4, 5, 7, 10, 10, "EDCCBBAAFF" "HDDCCGGAAF" "HHDDIIGGAJ" "JHHKKIIGLJ" "JJNNKKIMLL"
      "LPPNNKOMML" "RRPPNQOOMM" "TRRPSQQOOT" "TTRBSSQQEE" "ETCBBSSFFE"},
    {4, 5, 8, 10, 10, "DDDCBCBAAA" "DFDFBBBEEE" "HFFFGGGEHE" "HJJJGIGIHH" "LJKJKIIILL"
      "LNKKKMMMLN" "NNPPPMOMON" "RRPQPQOOOR" "TRTQQQSSSR" "TTTCCCSASA"},
    {4, 5, 9, 5, 5, "BAAAC" "BBBAD" "DDBED" "EDCEE" "EACCC"},
    {4, 5, 10, 5, 10, "BAAAC" "BBBAD" "DBEDD" "DFEEE" "FFFEG" "GGFHG" "GIHHH" "JIIIH" "JJICJ"
      "CJACC"},
    {4, 5, 11, 5, 10, "BAAAB" "AABBB" "DDCCC" "DCCDD" "FEEFF" "EEFFE" "HHGGH" "GGGHH" "IIIJJ"
      "IJJJI"},
    {4, 5, 12, 10, 5, "DDDCCCBAFE" "HDGGGBBBFE" "HDJGIIIFFF" "HHJGCIAAAH" "EJJJCIBAEE"},
    {4, 6, 1, 12, 2, "BBBBBBAAAAAA" "DDDDDDCCCCCC"},
    {4, 6, 2, 6, 4, "BBBBBA" "BAAAAA" "DDDDDC" "DCCCCC"},
    {4, 6, 3, 6, 4, "BBBBBA" "ABAAAA" "DDDDDC" "CDCCCC"},
    {4, 6, 4, 6, 4, "BBBBBA" "AABAAA" "DDDDDC" "CCDCCC"},
    {4, 6, 5, 6, 6, "BBAAAA" "CAACCC" "DDCCDD" "EEEDDE" "FFFFEE" "FBBBBF"},
    {4, 6, 6, 6, 4, "BBBBAA" "BBAAAA" "DDDDCC" "DDCCCC"},
    {4, 6, 7, 6, 4, "ABBAAA" "BBBBAA" "CDDCCC" "DDDDCC"},
    {4, 6, 8, 6, 6, "BBBAAA" "CAAACC" "DDCCCD" "EEEDDD" "EFFFEE" "FFBBBF"},
    {4, 6, 9, 6, 4, "ABBBAA" "BBBAAA" "CDDDCC" "DDDCCC"},
    {4, 6, 10, 6, 4, "BBBAAA" "BBBAAA" "DDDCCC" "DDDCCC"},
    {4, 6, 11, 4, 6, "BAAA" "BBAA" "BBBA" "DCCC" "DDCC" "DDDC"},
    {4, 6, 12, 6, 6, "CCCBBA" "DDCCBD" "EDDCEE" "EEDFFF" "FEAAAF" "FBBBAA"},
    {4, 6, 13, 8, 6, "BBBBAAAA" "DBDBCACA" "DDDDCCCC" "FFFFEEEE" "HFHFGEGE" "HHHHGGGG"},
    {4, 6, 14, 6, 4, "BBBAAA" "CBDDAC" "CBBDAA" "CCDDDC"},
    {4, 6, 15, 6, 6, "BBBAAA" "DBBCAA" "DCCCDD" "DFCCED" "FFEEEF" "FFBEEA"},
    {4, 6, 16, 6, 6, "CBBBAA" "CCBBDC" "CCEDDD" "FEEEDD" "FFEEAF" "FFBAAA"},
    {4, 6, 17, 6, 12, "CCCCBA" "DCBBBB" "DDDEBD" "DEEEEF" "FFGEFF" "GGGGHF" "HIGHHH" "IIIJHI"
      "KIJJJJ" "KKLJKK" "KLLLLA" "ACLAAA"},
    {4, 6, 18, 6, 12, "CBAAAA" "CCCCDA" "CDDDDE" "EEEFDE" "FFFFGE" "GGHFGG" "HHHIGH" "IJHIII"
      "JJKIJJ" "LJKKKK" "LBKLLL" "LBBBBA"},
    {4, 6, 19, 6, 6, "DCCCBA" "DDDCBE" "EEDCFE" "FEDAFF" "FEBAAA" "FCBBBA"},
    {4, 6, 20, 6, 6, "CBBBBA" "DBAAAA" "DEADDD" "EEFDEE" "FFFCEF" "CCCCBF"},
    {4, 6, 21, 6, 6, "CBAAAA" "DBADDD" "EEADEE" "FFFDEF" "CCCCEF" "CBBBBF"},
    {4, 6, 22, 8, 3, "BBBBAAAA" "BCDBADCA" "CCDDDDCC"},
    {4, 6, 23, 4, 6, "BAAA" "BBBA" "DBCA" "DCCC" "DDDC" "BDAC"},
    {4, 6, 24, 6, 6, "CCBBBA" "DCCCBB" "DCEEDD" "DDFEEE" "FFFEAA" "AAFFBA"},
    {4, 6, 25, 4, 6, "BBAA" "ABBA" "AABB" "DDCC" "CDDC" "CCDD"},
    {4, 6, 26, 4, 6, "BBAA" "BBAA" "ABBA" "DDCC" "DDCC" "CDDC"},
    {4, 6, 27, 4, 6, "BBAA" "BAAB" "BBAA" "DDCC" "DCCD" "DDCC"},
    {4, 6, 28, 6, 6, "CBBBAA" "CCCBBD" "DDCCED" "EDDFEE" "EEAFFF" "FBAAAF"},
    {4, 6, 29, 6, 6, "BBABAA" "CBBBCC" "CCDDCD" "EEEDDD" "EFEEFF" "FFAAAF"},
    {4, 6, 30, 6, 4, "ACBBBA" "CCCBDD" "DDCCAD" "DBBAAA"},
    {4, 6, 31, 6, 4, "CCCCBA" "CBBBBD" "DABDDD" "AACDAA"},
    {4, 6, 32, 6, 6, "CBAAAA" "CCDACC" "DDDDEC" "FDEEEE" "FFBEFF" "BBBBAF"},
    {4, 6, 33, 6, 4, "BBBAAA" "DDBCCA" "DBBCAA" "DDDCCC"},
    {4, 6, 34, 12, 12, "FFFFEDCBAAAA" "FEEEECCCCHAG" "GGJEICHHHHGG" "JJJIIIILHKGJ" "NJMILLLLKKKK"
      "NMMMMPLOKNNN" "RMPPPPOOOOQN" "RRRTPSOQQQQR" "TTTTSSSSVQUR" "UXTWSVVVVUUU" "XXWWWWDVBUXX"
      "XFWDDDDBBBBA"},
    {4, 6, 35, 4, 6, "BAAA" "BBBA" "BDCA" "DDCD" "CDCC" "BDCA"},
// Triangular and hexagonal cells: each file says how its tables cover the cells.
#include "scene/pavement_layouts_triangles.inc"
#include "scene/pavement_layouts_hexagons.inc"
};
// clang-format on

inline const PavementLayout* pavement_layout(int sides, int tiles, int number) {
    for (const PavementLayout& l : kPavementLayouts)
        if (l.sides == sides && l.tiles == tiles && l.number == number) return &l;
    return nullptr;
}

}  // namespace lumen::scene
