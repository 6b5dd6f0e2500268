// The technique advisor's rule (bench/advisor.hpp) on a synthetic device: measured points given
// as numbers, so every case states its pick.
#include "bench/advisor.hpp"

#include <doctest/doctest.h>

#include <algorithm>

using namespace strata;

namespace {

AdvisorPoint point(const std::string& id, double ms, double rmse) {
    AdvisorPoint p;
    p.candidate.id = id;
    p.frameMs = ms;
    p.techniqueMs = ms;
    p.rmse = rmse;
    return p;
}

// A device where the exact techniques cost 6-12 ms and the others 1-4 ms; exact means round-off
// (1e-6) against the reference.
std::vector<AdvisorPoint> synthetic() {
    std::vector<AdvisorPoint> p = {point("abuffer", 8.0, 1e-6),      point("ll", 6.0, 1e-6),
                                   point("f2b", 12.0, 8e-5),         point("kbuffer", 4.0, 0.02),
                                   point("wboit", 1.0, 0.07),        point("blend-unsorted", 1.5, 0.26),
                                   point("stochastic", 2.0, 0.05),   point("dual", 9.0, 8e-5)};
    markPareto(p);
    return p;
}

const std::string& pickedId(const std::vector<AdvisorPoint>& p, const AdvisorCriteria& c) {
    const AdvisorPick pick = recommend(p, c);
    REQUIRE(pick.index >= 0);
    return p[std::size_t(pick.index)].candidate.id;
}

}  // namespace

TEST_CASE("advisor: the Pareto front is what nothing beats in both time and error") {
    const auto p = synthetic();
    std::vector<std::string> front;
    for (const auto& x : p)
        if (x.pareto) front.push_back(x.candidate.id);
    std::sort(front.begin(), front.end());
    // wboit is fastest; stochastic beats it on error; kbuffer on error again; ll is exact.
    CHECK(front == std::vector<std::string>{"kbuffer", "ll", "stochastic", "wboit"});
}

TEST_CASE("advisor: a budget picks the most accurate configuration whose frame fits it") {
    const auto p = synthetic();
    CHECK(pickedId(p, {5.0, std::nullopt}) == "kbuffer");
    CHECK(pickedId(p, {7.0, std::nullopt}) == "ll");
    CHECK(pickedId(p, {100.0, std::nullopt}) == "ll");  // equal errors: the faster
    CHECK(pickedId(p, {1.9, std::nullopt}) == "wboit");
    // Nothing fits: the fastest, and the reason says so.
    const AdvisorPick none = recommend(p, {0.5, std::nullopt});
    CHECK(p[std::size_t(none.index)].candidate.id == "wboit");
    CHECK(none.reason.find("nothing fits") != std::string::npos);
}

TEST_CASE("advisor: an error bound picks the fastest configuration within it; none given means 1/255") {
    const auto p = synthetic();
    CHECK(pickedId(p, {std::nullopt, 0.06}) == "stochastic");
    CHECK(pickedId(p, {std::nullopt, 0.03}) == "kbuffer");
    CHECK(pickedId(p, {std::nullopt, std::nullopt}) == "ll");  // 1/255 leaves the exact ones
    const AdvisorPick none = recommend(p, {std::nullopt, 1e-9});
    CHECK(p[std::size_t(none.index)].candidate.id == "ll");  // the most accurate, fastest of equals
    CHECK(none.reason.find("nothing is within") != std::string::npos);
}

TEST_CASE("advisor: both bounds pick the most accurate within both, else fall back to the budget") {
    const auto p = synthetic();
    CHECK(pickedId(p, {5.0, 0.06}) == "kbuffer");
    const AdvisorPick fallback = recommend(p, {1.9, 0.01});  // only wboit fits 1.9 ms, and it is not within 0.01
    CHECK(p[std::size_t(fallback.index)].candidate.id == "wboit");
    CHECK(fallback.reason.find("nothing met both") != std::string::npos);
}

TEST_CASE("advisor: the pick is never beaten by more than 10 % in error by a measured point within its budget") {
    // The acceptance rule, over every budget between the fastest and the slowest point.
    const auto p = synthetic();
    for (double budget = 1.0; budget <= 12.0; budget += 0.25) {
        CAPTURE(budget);
        const AdvisorPick pick = recommend(p, {budget, std::nullopt});
        const AdvisorPoint& chosen = p[std::size_t(pick.index)];
        CHECK(chosen.frameMs <= budget);
        for (const auto& q : p)
            if (q.frameMs <= budget) CHECK(q.rmse >= chosen.rmse * 0.9 - 1e-12);
    }
}

TEST_CASE("advisor: near-equal errors cannot chain the pick away from the least error") {
    // Each point is within 1 % of the next and faster: a pairwise "equal within 1 %, then faster"
    // would walk to the last; the rule measures from the least error.
    std::vector<AdvisorPoint> p;
    double rmse = 1.0e-3, ms = 10.0;
    for (int i = 0; i < 10; ++i, rmse *= 1.009, ms -= 0.5) p.push_back(point("c" + std::to_string(i), ms, rmse));
    markPareto(p);
    const AdvisorPick pick = recommend(p, {100.0, std::nullopt});
    CHECK(p[std::size_t(pick.index)].candidate.id == "c1");  // 1.009e-3 is within 1 % of 1e-3 and faster; 1.018e-3 is not
}

TEST_CASE("advisor: the candidates are each technique's defaults, then its trading settings") {
    const auto all = advisorCandidates({}, false);
    CHECK(std::none_of(all.begin(), all.end(), [](const AdvisorCandidate& c) { return c.id == "floor"; }));
    CHECK(std::all_of(all.begin(), all.end(), [](const AdvisorCandidate& c) { return c.assignments.empty(); }));
    const auto ll = advisorCandidates({"ll"}, true);
    std::vector<std::string> labels;
    for (const auto& c : ll) labels.push_back(c.label());
    // Capacities around the default 8, the tail; precision only sizes the tail's targets, so not alone.
    CHECK(labels == std::vector<std::string>{"ll", "ll capacity=4", "ll capacity=16", "ll capacity=32", "ll tail=true"});
    const auto f2b = advisorCandidates({"f2b"}, true);
    REQUIRE(f2b.size() == 2);
    CHECK(f2b[1].label() == "f2b precision=16");
    const auto wboit = advisorCandidates({"wboit"}, true);  // default 16: the other is 32
    REQUIRE(wboit.size() == 2);
    CHECK(wboit[1].label() == "wboit precision=32");
    CHECK_THROWS_AS(advisorCandidates({"nosuch"}, true), std::invalid_argument);
    CHECK(advisorCandidates({"ll", "ll"}, false).size() == 1);  // an id given twice counts once
    // The references are measured at their defaults only (a bench compares them with themselves).
    CHECK(advisorCandidates({"abuffer", "abuffer-volume"}, true).size() == 2);
}
