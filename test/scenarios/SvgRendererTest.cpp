// SvgRenderer: well-formed SVG (parsed with tinyxml2) holding the scene layers, one polyline per label and the
// chosen belief particles; malformed recordings name what is wrong.
#include <gtest/gtest.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "ExpectError.h"
#include "SvgTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/ExperimentRunner.h"
#include "ropras/scenarios/SvgRenderer.h"
#include "scenarios/ToyScenario.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {
        using nlohmann::json;

        json box(std::vector<double> lo, std::vector<double> hi)
        {
            return json::array({lo, hi});
        }

        /** \brief A hand-made 3-D recording with two drones and a target, two recorded beliefs of 3 particles. */
        json droneRecording()
        {
            json r;
            r["scenario"] = "multi-drone";
            r["solver"] = "ropras3";
            r["heuristic"] = "dynamic";
            r["success"] = true;
            r["steps"] = 2;
            r["seed"] = 5;
            r["labels"] = {"drone1", "drone2", "target"};
            r["scene"] = {{"dims", 3},
                          {"bounds", box({-15, -15, -2}, {15, 15, 2})},
                          {"walls", json::array()},
                          {"obstacles", json::array({box({0, 0, -2}, {1, 1, -1}), box({2, 2, 1}, {3, 3, 2})})},
                          {"danger_zones", json::array({box({-5, -5, -2}, {-4, -4, 2})})},
                          {"observation_zones", json::array({json::array({1.0, 2.0, 0.0})})},
                          {"starts", json::array({json::array({-10.0, -10.0, 0.0}), json::array({10.0, -10.0, 0.0})})},
                          {"capture_radius", 0.5},
                          {"detection_range", 3.0},
                          {"teleport_axes", json::array({"x", "y"})}};
            r["trajectory"] = json::array();
            for (int t = 0; t < 3; ++t)
            {
                r["trajectory"].push_back(
                    json::array({json::array({-10.0 + t, -10.0, 0.0}), json::array({10.0 - t, -10.0, 0.0}),
                                 json::array({0.0, 5.0 - t, 1.0})}));
            }
            r["beliefs"] = json::array();
            for (int step : {0, 2})
            {
                json particles = json::array();
                for (int p = 0; p < 3; ++p)
                {
                    particles.push_back(r["trajectory"][step]);
                }
                r["beliefs"].push_back({{"step", step}, {"particles", particles}});
            }
            return r;
        }

        /** \brief Parses \a svg; fails the test when it is not well-formed XML. */
        bool parse(const std::string &svg, tinyxml2::XMLDocument &doc)
        {
            const auto status = doc.Parse(svg.c_str(), svg.size());
            EXPECT_EQ(status, tinyxml2::XML_SUCCESS) << doc.ErrorStr();
            return status == tinyxml2::XML_SUCCESS;
        }

        std::size_t countElements(const tinyxml2::XMLElement *e, const std::string &name,
                                  const std::function<bool(const tinyxml2::XMLElement *)> &pred = {})
        {
            std::size_t n = 0;
            for (; e; e = e->NextSiblingElement())
            {
                if (name == e->Name() && (!pred || pred(e)))
                    ++n;
                n += countElements(e->FirstChildElement(), name, pred);
            }
            return n;
        }

        std::size_t countIn(const tinyxml2::XMLElement *group, const std::string &name)
        {
            return group ? countElements(group->FirstChildElement(), name) : 0;
        }
    }  // namespace

    TEST(SvgRenderer, DrawsEveryLayerTrajectoryAndBelief)
    {
        const json recording = droneRecording();
        const std::string svg = renderSvg(recording);
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(svg, doc));
        const auto *root = doc.RootElement();
        ASSERT_NE(root, nullptr);
        EXPECT_STREQ(root->Name(), "svg");
        EXPECT_STREQ(root->Attribute("xmlns"), "http://www.w3.org/2000/svg");
        EXPECT_EQ(countIn(findById(root, "obstacles"), "rect"), 2u);
        EXPECT_EQ(countIn(findById(root, "danger_zones"), "rect"), 1u);
        EXPECT_EQ(countIn(findById(root, "observation_zones"), "circle"), 1u) << "a landmark point";
        EXPECT_EQ(countIn(findById(root, "starts"), "circle"), 2u);
        EXPECT_EQ(findById(root, "walls"), nullptr) << "an empty layer draws nothing";
        EXPECT_NE(findById(root, "bounds"), nullptr);
        // one polyline per label with one point per step
        const auto *trajectory = findById(root, "trajectory");
        ASSERT_NE(trajectory, nullptr);
        std::vector<std::string> labels;
        for (const auto *p = trajectory->FirstChildElement("polyline"); p; p = p->NextSiblingElement("polyline"))
        {
            labels.push_back(p->Attribute("data-label"));
            const std::string points = p->Attribute("points");
            EXPECT_EQ(std::count(points.begin(), points.end(), ','), 3) << points;
        }
        EXPECT_EQ(labels, (std::vector<std::string>{"drone1", "drone2", "target"}));
        // the target is green, the drones differ
        EXPECT_EQ(countElements(trajectory->FirstChildElement(), "polyline",
                                [](const tinyxml2::XMLElement *e)
                                { return std::string(e->Attribute("stroke")) == "#2e7d32"; }),
                  1u);
        // beliefs: 2 steps x 3 particles x 3 points, each snapshot in the colour of its time
        const auto *beliefs = findById(root, "beliefs");
        ASSERT_NE(beliefs, nullptr);
        EXPECT_EQ(countElements(beliefs->FirstChildElement(), "circle",
                                [](const tinyxml2::XMLElement *e)
                                { return e->Attribute("class") && std::string(e->Attribute("class")) == "particle"; }),
                  18u);
        const auto *first = beliefs->FirstChildElement("g");
        ASSERT_NE(first, nullptr);
        ASSERT_NE(first->NextSiblingElement("g"), nullptr);
        EXPECT_STRNE(first->Attribute("fill"), first->NextSiblingElement("g")->Attribute("fill"));
        // detection range around both drones, capture radius around the target
        EXPECT_EQ(countIn(findById(root, "detection_range"), "circle"), 2u);
        EXPECT_EQ(countIn(findById(root, "capture_radius"), "circle"), 1u);
        // the title names scenario, solver, outcome and steps
        EXPECT_NE(svg.find("multi-drone / ropras3 (dynamic)"), std::string::npos);
        EXPECT_NE(svg.find("success, 2 steps"), std::string::npos);
        // higher boxes are drawn darker (top view shading by z)
        const auto *obstacles = findById(root, "obstacles");
        const auto *low = obstacles->FirstChildElement("rect");
        const auto *high = low->NextSiblingElement("rect");
        EXPECT_LT(low->DoubleAttribute("fill-opacity"), high->DoubleAttribute("fill-opacity"));
    }

    TEST(SvgRenderer, ChosenBeliefStepsOnly)
    {
        SvgOptions options;
        options.beliefSteps = {2};
        const std::string svg = renderSvg(droneRecording(), options);
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(svg, doc));
        const auto *beliefs = findById(doc.RootElement(), "beliefs");
        ASSERT_NE(beliefs, nullptr);
        EXPECT_EQ(countElements(beliefs->FirstChildElement(), "g"), 1u);
        EXPECT_STREQ(beliefs->FirstChildElement("g")->Attribute("data-step"), "2");
        options.beliefSteps = {1};
        expectErrorMentions([&] { renderSvg(droneRecording(), options, "rec.json"); },
                            {"rec.json", "belief step 1", "recorded steps: 0, 2"});
    }

    // A recording written by the runner on the toy scenario renders; the map keeps the bounds' aspect ratio.
    TEST(SvgRenderer, RendersARunnerRecording)
    {
        const auto toy = makeToyScenario(15);
        ExperimentSettings s;
        s.run.solver = "pomcp";
        s.run.budget = pomdp::Budget::ofSimulations(20);
        s.episodes = 1;
        s.threads = 1;
        const auto dir = std::filesystem::temp_directory_path() / ("ropras-svg-test-" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir);
        s.recordDir = dir.string();
        s.record.beliefEvery = 5;
        const auto records = runExperiment(*toy, s);
        const auto path = dir / "toy-pomcp-0.json";
        const json recording = loadRecording(path.string());
        const std::string svg = renderSvg(recording, SvgOptions(), path.string());
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(svg, doc));
        const auto *root = doc.RootElement();
        EXPECT_EQ(countIn(findById(root, "walls"), "rect"), 1u);
        EXPECT_EQ(countIn(findById(root, "obstacles"), "rect"), 1u);
        EXPECT_EQ(countIn(findById(root, "goal"), "circle"), 1u);
        EXPECT_EQ(countIn(findById(root, "observation_zones"), "circle"), 1u);
        const auto *bounds = findById(root, "bounds");
        ASSERT_NE(bounds, nullptr);
        EXPECT_DOUBLE_EQ(bounds->DoubleAttribute("width"), 800.0);
        EXPECT_DOUBLE_EQ(bounds->DoubleAttribute("height"), 800.0);
        const auto *line = findById(root, "trajectory")->FirstChildElement("polyline");
        ASSERT_NE(line, nullptr);
        const std::string points = line->Attribute("points");
        EXPECT_EQ(static_cast<std::size_t>(std::count(points.begin(), points.end(), ',')),
                  records[0]["steps"].get<std::size_t>() + 1);
        std::filesystem::remove_all(dir);
    }

    // The target teleporting across the boundary is not drawn as a line across the map.
    TEST(SvgRenderer, TeleportsBreakTheLine)
    {
        json r = droneRecording();
        r["trajectory"][2][2] = json::array({14.5, 3.0, 1.0});  // from (0, 4) to the far side: a 14.5 m jump
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(renderSvg(r), doc));
        std::vector<std::string> pieces;
        const auto *trajectory = findById(doc.RootElement(), "trajectory");
        ASSERT_NE(trajectory, nullptr);
        for (const auto *p = trajectory->FirstChildElement("polyline"); p; p = p->NextSiblingElement("polyline"))
        {
            if (std::string(p->Attribute("data-label")) == "target")
                pieces.push_back(p->Attribute("points"));
        }
        ASSERT_EQ(pieces.size(), 2u);
        EXPECT_EQ(std::count(pieces[0].begin(), pieces[0].end(), ','), 2);
        EXPECT_EQ(std::count(pieces[1].begin(), pieces[1].end(), ','), 1);
    }

    TEST(SvgRenderer, MalformedRecordingsNameTheProblem)
    {
        expectErrorMentions([] { renderSvg(json::array(), SvgOptions(), "r.json"); }, {"r.json", "JSON object"});
        json r = droneRecording();
        r.erase("scene");
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"r.json", "\"scene\""});
        r = droneRecording();
        r["scene"].erase("bounds");
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"scene.bounds", "missing"});
        r = droneRecording();
        r["scene"]["bounds"] = box({1, 1, 0}, {-1, -1, 1});
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"scene.bounds"});
        r = droneRecording();
        r["trajectory"][1].erase(2);
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"trajectory[1]", "3 point(s)"});
        r = droneRecording();
        r["trajectory"][2][0][1] = "north";
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"trajectory[2][0]", "finite number"});
        r = droneRecording();
        r["scene"]["obstacles"][1] = {{"colour", "red"}};
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"scene.obstacles[1]", "box"});
        r = droneRecording();
        r["labels"] = {"a", 3};
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"\"labels\""});
        r = droneRecording();
        r["beliefs"][0]["particles"][1] = json::array({json::array({0.0, 0.0})});
        expectErrorMentions([&] { renderSvg(r, SvgOptions(), "r.json"); }, {"beliefs[0].particles[1]"});
        // text is escaped
        r = droneRecording();
        r["scenario"] = "a<b&\"c\"";
        tinyxml2::XMLDocument doc;
        EXPECT_TRUE(parse(renderSvg(r), doc));
    }

    namespace
    {
        std::vector<const tinyxml2::XMLElement *> elementsOfClass(const tinyxml2::XMLElement *e, const std::string &cls)
        {
            std::vector<const tinyxml2::XMLElement *> out;
            for (; e; e = e->NextSiblingElement())
            {
                if (e->Attribute("class") && cls == e->Attribute("class"))
                    out.push_back(e);
                const auto inner = elementsOfClass(e->FirstChildElement(), cls);
                out.insert(out.end(), inner.begin(), inner.end());
            }
            return out;
        }
    }  // namespace

    // Axes carry metric ticks (1, 2 or 5 x 10^k m), 3-D problems get a side view (x, z) below the top view, the
    // paths carry arrowheads pointing the way they go, and the belief time ramp is labelled with its steps.
    TEST(SvgRenderer, AxesSideViewArrowsAndTimeLegend)
    {
        const std::string svg = renderSvg(droneRecording());
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(svg, doc));
        const auto *root = doc.RootElement();
        // bounds 30 m wide: ticks every 5 m, -15 ... 15 along x in both views
        std::vector<std::string> numbers;
        for (const auto *axes : elementsOfClass(root->FirstChildElement(), "axes"))
        {
            for (const auto *t = axes->FirstChildElement("text"); t; t = t->NextSiblingElement("text"))
                if (!t->Attribute("class"))
                    numbers.push_back(t->GetText());
        }
        EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "-15"), 3) << "x twice (top and side), y once";
        EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "5"), 3);
        EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "2"), 1) << "z from -2 to 2: ticks every 0.5 m";
        EXPECT_NE(svg.find(">x (m)<"), std::string::npos);
        EXPECT_NE(svg.find(">z (m)<"), std::string::npos);
        const auto *side = findById(root, "side_view");
        ASSERT_NE(side, nullptr) << "a 3-D problem has a side view";
        const auto sideObstacles = elementsOfClass(side->FirstChildElement(), "obstacles");
        ASSERT_EQ(sideObstacles.size(), 1u);
        EXPECT_EQ(countIn(sideObstacles[0], "rect"), 2u);
        // the side view's obstacle at z in [1, 2] sits above (smaller y) the one at z in [-2, -1]
        const auto *a = sideObstacles[0]->FirstChildElement("rect");
        EXPECT_GT(a->DoubleAttribute("y"), a->NextSiblingElement("rect")->DoubleAttribute("y"));
        // drone1 flies +x: every arrowhead's tip (its first point) lies right of its base
        const auto *trajectory = findById(root, "trajectory");
        ASSERT_NE(trajectory, nullptr);
        const auto arrows = elementsOfClass(trajectory->FirstChildElement(), "arrow");
        ASSERT_GE(arrows.size(), 3u * 8u);
        for (std::size_t i = 0; i < 8; ++i)
        {
            double x0, y0, x1, y1, x2, y2;
            ASSERT_EQ(
                std::sscanf(arrows[i]->Attribute("points"), "%lf,%lf %lf,%lf %lf,%lf", &x0, &y0, &x1, &y1, &x2, &y2),
                6);
            EXPECT_GT(x0, 0.5 * (x1 + x2));
        }
        const auto *ramp = findById(root, "time_legend");
        ASSERT_NE(ramp, nullptr);
        EXPECT_STREQ(elementsOfClass(ramp->FirstChildElement(), "time-last")[0]->GetText(), "2");
        // a 2-D recording has no side view
        json flat = droneRecording();
        flat["scene"]["dims"] = 2;
        flat["scene"]["bounds"] = box({-15, -15}, {15, 15});
        EXPECT_EQ(renderSvg(flat).find("side_view"), std::string::npos);
    }

    // Time labels of many snapshots at one place never overprint each other nor leave the map; the legend wraps
    // inside the picture.
    TEST(SvgRenderer, LabelsNeitherOverprintNorClip)
    {
        json r = droneRecording();
        r["labels"] = {"robot"};
        r["trajectory"] = json::array();
        r["beliefs"] = json::array();
        for (int t = 0; t < 30; ++t)
        {
            r["trajectory"].push_back({{14.8, 14.8, 0.0}});  // in the corner: labels must not leave the map
            r["beliefs"].push_back({{"step", t}, {"particles", {{{14.8, 14.8, 0.0}}}}});
        }
        r["scene"]["extra_layer_with_a_rather_long_name"] = json::array();
        const std::string svg = renderSvg(r);
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(svg, doc));
        const auto *root = doc.RootElement();
        const auto *bounds = findById(root, "bounds");
        const double left = bounds->DoubleAttribute("x"), top = bounds->DoubleAttribute("y");
        const double right = left + bounds->DoubleAttribute("width"), bottom = top + bounds->DoubleAttribute("height");
        const auto labels = elementsOfClass(root->FirstChildElement(), "time-label");
        ASSERT_GE(labels.size(), 1u);
        EXPECT_LT(labels.size(), 30u) << "labels that find no free spot are left out";
        std::vector<std::array<double, 4>> boxes;
        for (const auto *l : labels)
        {
            const double x = l->DoubleAttribute("x"), y = l->DoubleAttribute("y");
            const double w = 6.0 * std::string(l->GetText()).size();
            EXPECT_GE(x, left);
            EXPECT_LE(x + w, right);
            EXPECT_GE(y - 10.0, top);
            EXPECT_LE(y, bottom);
            for (const auto &b : boxes)
                EXPECT_FALSE(x < b[2] && b[0] < x + w && y - 10.0 < b[3] && b[1] < y) << l->GetText();
            boxes.push_back({x, y - 10.0, x + w, y});
        }
        const double width = root->DoubleAttribute("width");
        for (const auto *t = findById(root, "legend")->FirstChildElement("text"); t; t = t->NextSiblingElement("text"))
            EXPECT_LE(t->DoubleAttribute("x") + 7.0 * std::string(t->GetText()).size(), width) << t->GetText();
    }

    // A narrow map widens the picture so that the header's lines fit (about half an em a character).
    TEST(SvgRenderer, ANarrowMapWidensThePictureForTheHeader)
    {
        SvgOptions options;
        options.width = 60.0;
        const std::string svg = renderSvg(droneRecording(), options);
        tinyxml2::XMLDocument doc;
        ASSERT_TRUE(parse(svg, doc));
        const auto *root = doc.RootElement();
        const double width = root->DoubleAttribute("width");
        EXPECT_GT(width, 60.0 + 58.0 + 24.0);
        std::size_t lines = 0;
        for (const auto *t = root->FirstChildElement("text"); t; t = t->NextSiblingElement("text"), ++lines)
        {
            const double em = t->DoubleAttribute("font-size");
            EXPECT_LE(t->DoubleAttribute("x") + 0.5 * em * std::string(t->GetText()).size(), width) << t->GetText();
        }
        EXPECT_EQ(lines, 3u) << "title, outcome, what the views show";
        // a wide map keeps its own width
        options.width = 2000.0;
        ASSERT_TRUE(parse(renderSvg(droneRecording(), options), doc));
        EXPECT_DOUBLE_EQ(doc.RootElement()->DoubleAttribute("width"), 58.0 + 2000.0 + 24.0);
    }

    TEST(SvgRenderer, LoadRecordingNamesTheFile)
    {
        expectErrorMentions([] { loadRecording("/nonexistent/rec.json"); }, {"/nonexistent/rec.json"});
        const auto path =
            std::filesystem::temp_directory_path() / ("ropras-svg-malformed-" + std::to_string(::getpid()) + ".json");
        std::ofstream(path) << "{\"scene\": ";
        expectErrorMentions([&] { loadRecording(path.string()); }, {path.string(), "malformed JSON"});
        std::filesystem::remove(path);
    }
}  // namespace ropras::scenarios::test
