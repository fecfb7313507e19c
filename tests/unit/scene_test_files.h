// Scratch files for the scene tests: a temporary folder removed at the end of the test.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "io/raw_model.h"

class TempDir {
public:
    TempDir() {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                ("rt-" + std::string(test->test_suite_name()) + "-" + test->name() + "-" + std::to_string(getpid()));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() { std::filesystem::remove_all(path_); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string path(const std::string& name) const { return (path_ / name).string(); }

    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string p = path(name);
        std::filesystem::create_directories(std::filesystem::path(p).parent_path());
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }

private:
    std::filesystem::path path_;
};

// A RAW model of the given triangles (9 floats each) or spheres (4 floats each).
inline rt::Model rawModel(std::vector<float> triangles, std::vector<float> spheres = {}) {
    rt::Model m;
    m.triangleVertices = std::move(triangles);
    m.sphereData = std::move(spheres);
    return m;
}

// The exact error message of loading, or "" if it loads.
template <typename Load>
std::string inputErrorOf(Load&& load) {
    try {
        load();
    } catch (const rt::InputError& e) {
        return e.what();
    }
    return "";
}
