// SPDX-License-Identifier: MIT
// Shared by the bench programs: timing, image error, CSV output.
#pragma once

#include <prism/prism.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace bench {

/// Seconds taken by f(), the minimum over `repeats` runs (the least disturbed by other load).
template <class F>
double min_seconds(int repeats, F&& f)
{
    double best = 1e300;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

/// Root-mean-square difference over all pixels and channels.
inline double rmse(const prism::Film& a, const prism::Film& b)
{
    if (a.width() != b.width() || a.height() != b.height()) throw std::invalid_argument("rmse: films differ in size");
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels()[i][c]) - double(b.pixels()[i][c]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * double(a.pixels().size())));
}

/// A CSV file in bench/results (or the folder given), header written on open.
class Csv {
public:
    Csv(const std::filesystem::path& path, const std::string& header) : path_(path)
    {
        std::filesystem::create_directories(path.parent_path());
        file_ = std::fopen(path.c_str(), "w");
        if (file_ == nullptr) throw std::runtime_error("cannot write " + path.string());
        std::fprintf(file_, "%s\n", header.c_str());
    }
    Csv(const Csv&) = delete;
    Csv& operator=(const Csv&) = delete;
    ~Csv()
    {
        std::fclose(file_);
        std::printf("wrote %s\n", path_.c_str());
    }
    template <class... Args>
    void row(const char* format, Args... args)
    {
        std::fprintf(file_, format, args...);
        std::fputc('\n', file_);
    }

private:
    std::filesystem::path path_;
    std::FILE* file_;
};

/// The sampler a bench METHOD names after a colon and before `after`: "NAME:KIND" + after
/// (KIND a sampler_name), the suffix taken off `method`; nothing when it names none.
inline std::optional<prism::SamplerKind> take_sampler_suffix(std::string& method, std::string_view after)
{
    for (const prism::SamplerKind kind : prism::sampler_kinds) {
        const std::string suffix = std::string(":") + prism::sampler_name(kind) + std::string(after);
        if (!method.ends_with(suffix)) continue;
        method.resize(method.size() - suffix.size());
        return kind;
    }
    return std::nullopt;
}

/// The sampler a bench METHOD names: "NAME:independent", "NAME:zsobol", "NAME:halton" (and
/// "NAME:sobol") are NAME with that SamplerKind, the suffix taken off `method`; anything
/// else Owen-scrambled Sobol points, per pixel.
inline prism::SamplerKind take_sampler(std::string& method)
{
    return take_sampler_suffix(method, "").value_or(prism::SamplerKind::sobol);
}

} // namespace bench
