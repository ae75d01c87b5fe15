// The tier promise over many layouts (bench_mb_families --layouts): the square family's layouts,
// the CSV's layout column and the table of means over the layouts (tools/bench/common/mb_doc_tables.*).
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "mb_doc_tables.hpp"
#include "mb_families.hpp"

using namespace sfx::tools;

namespace {

// A scratch CSV, removed when the test ends.
struct ScratchCsv {
    std::string path = (std::filesystem::temp_directory_path() / "sfx_test_mb_layouts.csv").string();
    explicit ScratchCsv(const std::string& text) { std::ofstream(path) << text; }
    ~ScratchCsv() { std::remove(path.c_str()); }
};

}  // namespace

TEST_CASE("mb layouts: the square's layout 1 is the scene as given, the others shift it within a stripe period", "[motion_blur][families]") {
    const FamilyCase given = makeFamilyCase("square", 9.5, 1, 320, 240);
    REQUIRE(given.scene.objects.size() == 2);
    CHECK(given.scene.objects[1].centre[0] == 160.0);  // edges at 128 and 192, stripe boundaries
    bool moved = false;
    for (uint32_t layout = 2; layout <= 16; ++layout) {
        const FamilyCase c = makeFamilyCase("square", 9.5, layout, 320, 240);
        const double shift = c.scene.objects[1].centre[0] - 160.0;
        CHECK(shift >= 0.0);
        CHECK(shift < 8.0);
        CHECK(c.scene.objects[1].centre[1] == given.scene.objects[1].centre[1]);
        moved = moved || shift > 0.5;
    }
    CHECK(moved);
    // The same layout twice is the same scene.
    CHECK(makeFamilyCase("square", 9.5, 7, 320, 240).scene.objects[1].centre == makeFamilyCase("square", 9.5, 7, 320, 240).scene.objects[1].centre);
}

TEST_CASE("mb layouts: the table gives the worst mean over the layouts, the cases below and the worst case", "[motion_blur]") {
    // Family f at 7 and 9 px over layouts 1-3; moving region high - current: at 7 px +0.3, -0.1,
    // +0.1 (mean +0.1); at 9 px -0.2, -0.4, +0.3 (mean -0.1, the worst; the worst case -0.4 on
    // layout 2). Frame always equal; the edges empty ("-").
    std::string csv = "family,split,speed_px,layout,tier,source,psnr_moving,psnr_frame,psnr_leading,psnr_trailing\n";
    const double speeds[] = {7, 9};
    const double high[2][3] = {{30.3, 29.9, 30.1}, {29.8, 29.6, 30.3}};
    for (int s = 0; s < 2; ++s)
        for (int layout = 1; layout <= 3; ++layout) {
            const std::string key = "f,held-out," + std::to_string(int(speeds[s])) + "," + std::to_string(layout);
            csv += key + ",current,reference,30.0,40.0,-,-\n";
            csv += key + ",high,reference," + std::to_string(high[s][layout - 1]) + ",40.0,-,-\n";
            csv += key + ",high,vulkan,10.0,10.0,-,-\n";  // not the CPU reference: left out
        }
    ScratchCsv file(csv);
    sfx::Result<std::vector<MbFamilyRow>> rows = readMbFamilyCsv(file.path);
    REQUIRE(rows);
    REQUIRE(rows->size() == 18);
    CHECK(rows->at(3).layout == 2);
    const std::string table = mbLayoutsTable(rows.value(), "setup");
    CHECK(table.rfind("setup", 0) == 0);
    CHECK(table.find("| f | 3 | -0.10 at 9 px; 3 of 6, worst -0.40 (9 px, layout 2) | +0.00; 0 of 6 | - | - |") != std::string::npos);
}

TEST_CASE("mb layouts: a CSV without a layout column reads layout 0", "[motion_blur]") {
    ScratchCsv file("family,speed_px,tier,psnr_moving\nf,6,current,30\nf,6,high,31\n");
    sfx::Result<std::vector<MbFamilyRow>> rows = readMbFamilyCsv(file.path);
    REQUIRE(rows);
    REQUIRE(rows->size() == 2);
    CHECK(rows->at(0).layout == 0);
    CHECK(rows->at(1).moving == 31.0);
}
