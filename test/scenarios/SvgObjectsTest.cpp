// SvgObjects in `ropras render`: the scene's objects (cans) at the chosen steps in both views, held ones at the
// holder between their grasp and release events, their belief particles in one colour per object, the slots with
// the reserved one marked; malformed "objects" keys name the key. Shelf-Move's own scene and event names agree.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ExpectError.h"
#include "SvgTestUtil.h"
#include "ropras/core/Error.h"
#include "ropras/scenarios/SvgRenderer.h"
#include "ropras/scenarios/manipulation/ShelfMoveScenario.h"

namespace ropras::scenarios::test
{
    using ropras::test::expectErrorMentions;

    namespace
    {
        using nlohmann::json;
        using Element = tinyxml2::XMLElement;

        constexpr int STEPS = 6;  // trajectory points 0..5
        constexpr double CAN_RADIUS = 0.03, CAN_HEIGHT = 0.14;

        /// end effector at (0.1 t, 0, 0.5); can0 still at (0.8, 0, 0.64); can1 follows the hand from its grasp
        /// (step 2) to its release (step 4, on slot 0) and stays there
        json handPoint(int t)
        {
            return json::array({0.1 * t, 0.0, 0.5});
        }

        json shelfRecording()
        {
            json r;
            r["scenario"] = "shelf-move";
            r["solver"] = "ropras3";
            r["success"] = false;
            r["steps"] = STEPS - 1;
            r["labels"] = {"end_effector", "can0", "can1"};
            r["scene"] = {
                {"dims", 3},
                {"bounds", json::array({json::array({-0.2, -0.6, 0.0}), json::array({1.0, 0.6, 1.2})})},
                {"obstacles",
                 json::array({json::array({json::array({0.5, -0.45, 0.53}), json::array({0.9, 0.45, 0.57})})})},
                {"objects",
                 {{"labels", {"can0", "can1"}},
                  {"radius", CAN_RADIUS},
                  {"height", CAN_HEIGHT},
                  {"holder", "end_effector"},
                  {"grasp_event", "grasp-"},
                  {"release_event", "release-"}}},
                {"slots", json::array({{{"center", {0.56, -0.22, 0.99}}, {"radius", CAN_RADIUS}},
                                       {{"center", {0.56, 0.0, 0.99}}, {"radius", CAN_RADIUS}}})},
                {"reserved_slot", 1}};
            r["trajectory"] = json::array();
            for (int t = 0; t < STEPS; ++t)
            {
                // while held, the can's centre sits 1 cm off the hand (as a grasp offset would put it)
                const json can1 = t < 2   ? json::array({0.62, 0.065, 0.64})
                                  : t < 4 ? json::array({0.1 * t + 0.01, 0.0, 0.5})
                                          : json::array({0.56, -0.22, 0.99});
                r["trajectory"].push_back(json::array({handPoint(t), json::array({0.8, 0.0, 0.64}), can1}));
            }
            r["events"] = json::array({{{"step", 2}, {"event", "grasp-can1"}},
                                       {{"step", 4}, {"event", "release-can1-slot0+moved"}},
                                       {{"step", 5}, {"event", "grasp-can10"}}});  // another can's name, not can1's
            // beliefs: 3 particles at step 0, 2 at step 5
            r["beliefs"] = json::array();
            for (const auto &[step, n] : std::vector<std::pair<int, int>>{{0, 3}, {5, 2}})
            {
                json particles = json::array();
                for (int p = 0; p < n; ++p)
                {
                    json points = r["trajectory"][step];
                    points[1][1] = 0.01 * p;  // spread can0's particles in y
                    particles.push_back(points);
                }
                r["beliefs"].push_back({{"step", step}, {"particles", particles}});
            }
            return r;
        }

        void collect(const Element *e, const std::function<bool(const Element *)> &pred,
                     std::vector<const Element *> &out)
        {
            for (; e; e = e->NextSiblingElement())
            {
                if (pred(e))
                    out.push_back(e);
                collect(e->FirstChildElement(), pred, out);
            }
        }

        /// the elements under \a root whose class is exactly \a cls
        std::vector<const Element *> withClass(const Element *root, const std::string &cls)
        {
            std::vector<const Element *> out;
            if (root)
                collect(
                    root->FirstChildElement(),
                    [&](const Element *e) { return e->Attribute("class") && cls == e->Attribute("class"); }, out);
            return out;
        }

        std::vector<const Element *> cans(const Element *view)
        {
            auto out = withClass(view, "can");
            const auto held = withClass(view, "can held");
            out.insert(out.end(), held.begin(), held.end());
            return out;
        }

        struct Picture
        {
            tinyxml2::XMLDocument doc;
            const Element *top{nullptr}, *side{nullptr};
        };

        void render(const json &recording, const SvgOptions &options, Picture &p)
        {
            const std::string svg = renderSvg(recording, options);
            ASSERT_EQ(p.doc.Parse(svg.c_str(), svg.size()), tinyxml2::XML_SUCCESS) << p.doc.ErrorStr();
            p.top = p.doc.RootElement();
            p.side = findById(p.top, "side_view");
        }

        /// the pixel frame of the top view (x, y) from its bounds rectangle: x = left + (wx + 0.2) * scale
        struct TopFrame
        {
            double left, top, scale;
            double x(double wx) const { return left + (wx + 0.2) * scale; }
            double y(double wy) const { return top + (0.6 - wy) * scale; }
        };
        TopFrame topFrame(const Element *root)
        {
            const auto *bounds = findById(root, "bounds");
            return {bounds->DoubleAttribute("x"), bounds->DoubleAttribute("y"), bounds->DoubleAttribute("width") / 1.2};
        }
    }  // namespace

    TEST(SvgObjects, BothViewsDrawEveryObjectAtEveryChosenStep)
    {
        SvgOptions options;
        options.armSteps = {0, 3, 5};
        Picture p;
        ASSERT_NO_FATAL_FAILURE(render(shelfRecording(), options, p));
        ASSERT_NE(p.side, nullptr) << "a 3-D recording has a side view";
        const auto *objects = findById(p.top, "objects");
        ASSERT_NE(objects, nullptr);
        // 2 objects x 3 chosen steps; the side view's are inside side_view, the top view's are not
        const auto topCans = cans(objects);
        EXPECT_EQ(topCans.size(), 6u);
        const auto sideCans = cans(p.side);
        EXPECT_EQ(sideCans.size(), 6u);
        for (const auto *c : topCans)
            EXPECT_STREQ(c->Name(), "circle") << "top view: discs";
        for (const auto *c : sideCans)
            EXPECT_STREQ(c->Name(), "rect") << "side view: radius x height rectangles";
        // a side-view can is 2 r wide and h tall, its top at the centre's z + h / 2
        const TopFrame f = topFrame(p.top);
        const auto sideBounds = withClass(p.side, "bounds");
        ASSERT_EQ(sideBounds.size(), 1u);
        for (const auto *c : sideCans)
        {
            EXPECT_NEAR(c->DoubleAttribute("width"), 2 * CAN_RADIUS * f.scale, 0.01);
            EXPECT_NEAR(c->DoubleAttribute("height"), CAN_HEIGHT * f.scale, 0.01);
            if (std::string(c->Attribute("data-label")) == "can0")
            {
                const double zTop = sideBounds[0]->DoubleAttribute("y") + (1.2 - (0.64 + 0.5 * CAN_HEIGHT)) * f.scale;
                EXPECT_NEAR(c->DoubleAttribute("y"), zTop, 0.01);
            }
        }
        // per step, each object once
        std::map<std::string, int> perStep;
        for (const auto *c : topCans)
            ++perStep[std::string(c->Attribute("data-step")) + "/" + c->Attribute("data-label")];
        EXPECT_EQ(perStep,
                  (std::map<std::string, int>{
                      {"0/can0", 1}, {"0/can1", 1}, {"3/can0", 1}, {"3/can1", 1}, {"5/can0", 1}, {"5/can1", 1}}));
        // shelf boards in both views
        EXPECT_NE(findById(p.top, "obstacles"), nullptr);
        EXPECT_EQ(withClass(p.side, "obstacles").size(), 1u);
    }

    TEST(SvgObjects, DefaultStepsAreTheArmsSpreadOverTheEpisode)
    {
        Picture p;
        ASSERT_NO_FATAL_FAILURE(render(shelfRecording(), SvgOptions(), p));
        // 6 frames: every step 0..5, 2 objects each, in both views
        EXPECT_EQ(cans(findById(p.top, "objects")).size(), 12u);
        EXPECT_EQ(cans(p.side).size(), 12u);
    }

    TEST(SvgObjects, HeldCanIsDrawnAtTheHolderBetweenGraspAndRelease)
    {
        SvgOptions options;
        options.armSteps = {1, 2, 3, 4, 5};
        Picture p;
        ASSERT_NO_FATAL_FAILURE(render(shelfRecording(), options, p));
        const TopFrame f = topFrame(p.top);
        const auto held = withClass(findById(p.top, "objects"), "can held");
        ASSERT_EQ(held.size(), 2u) << "can1 at steps 2 and 3 (grasped at 2, released at 4; grasp-can10 is not can1's)";
        for (const auto *c : held)
        {
            EXPECT_STREQ(c->Attribute("data-label"), "can1");
            const int step = c->IntAttribute("data-step");
            EXPECT_TRUE(step == 2 || step == 3) << step;
            EXPECT_NEAR(c->DoubleAttribute("cx"), f.x(0.1 * step), 0.01) << "at the hand, not the can's own point";
            EXPECT_NEAR(c->DoubleAttribute("cy"), f.y(0.0), 0.01);
            EXPECT_STREQ(c->Attribute("fill"), "none");
        }
        EXPECT_EQ(withClass(p.side, "can held").size(), 2u);
        // after the release the can is at its recorded point (slot 0) and not held
        for (const auto *c : withClass(findById(p.top, "objects"), "can"))
        {
            if (std::string(c->Attribute("data-label")) == "can1" && c->IntAttribute("data-step") >= 4)
            {
                EXPECT_NEAR(c->DoubleAttribute("cx"), f.x(0.56), 0.01);
                EXPECT_NEAR(c->DoubleAttribute("cy"), f.y(-0.22), 0.01);
            }
        }
    }

    TEST(SvgObjects, ObjectParticlesPerCanMatchTheRecordedBeliefs)
    {
        const json recording = shelfRecording();
        Picture p;
        ASSERT_NO_FATAL_FAILURE(render(recording, SvgOptions(), p));
        std::size_t recorded = 0;  // particles per label over all recorded beliefs
        for (const auto &b : recording["beliefs"])
            recorded += b["particles"].size();
        ASSERT_EQ(recorded, 5u);
        for (const Element *view : {findById(p.top, "object_beliefs"), p.side})
        {
            ASSERT_NE(view, nullptr);
            std::map<std::string, std::size_t> perCan;
            std::map<std::string, std::string> colour;
            for (const auto *e : withClass(view, "particle object-particle"))
            {
                const auto *group = e->Parent()->ToElement();
                ++perCan[group->Attribute("data-label")];
                colour[group->Attribute("data-label")] = group->Attribute("fill");
            }
            EXPECT_EQ(perCan, (std::map<std::string, std::size_t>{{"can0", recorded}, {"can1", recorded}}));
            EXPECT_NE(colour["can0"], colour["can1"]) << "one colour per object";
        }
        // the time-coloured belief loop draws only the end effector's particles (the cans' are not drawn twice)
        EXPECT_EQ(withClass(findById(p.top, "beliefs"), "particle").size(), recorded);
        // can0's particles are where the belief put them: y = 0, 0.01, 0.02 at step 0
        const TopFrame f = topFrame(p.top);
        std::vector<double> ys;
        for (const auto *e : withClass(findById(p.top, "object_beliefs"), "particle object-particle"))
        {
            if (std::string(e->Parent()->ToElement()->Attribute("data-label")) == "can0" &&
                e->IntAttribute("data-step") == 0)
                ys.push_back(e->DoubleAttribute("cy"));
        }
        ASSERT_EQ(ys.size(), 3u);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(ys[std::size_t(k)], f.y(0.01 * k), 0.01);
    }

    TEST(SvgObjects, TheReservedSlotIsMarked)
    {
        Picture p;
        ASSERT_NO_FATAL_FAILURE(render(shelfRecording(), SvgOptions(), p));
        const auto *slots = findById(p.top, "slots");
        const auto reserved = withClass(slots, "slot reserved");
        ASSERT_EQ(reserved.size(), 1u);
        EXPECT_STREQ(reserved[0]->Attribute("data-slot"), "1");
        EXPECT_EQ(withClass(slots, "slot").size(), 1u);
        EXPECT_EQ(withClass(p.side, "slot reserved").size(), 1u);
        EXPECT_EQ(withClass(p.side, "slot").size(), 1u);
        // the reserved slot is drawn last (on top of a slot it overlaps in the side view)
        EXPECT_EQ(slots->LastChildElement(), reserved[0]);
        // the legend names the objects, the slots and the reserved slot
        const std::string svg = renderSvg(shelfRecording());
        for (const char *entry : {"can0 (body and belief particles)", "reserved slot", "slots (dashed)"})
            EXPECT_NE(svg.find(entry), std::string::npos) << entry;
    }

    TEST(SvgObjects, MalformedObjectsNameTheKey)
    {
        const auto broken = [](const std::function<void(json &)> &edit)
        {
            json r = shelfRecording();
            edit(r["scene"]);
            return r;
        };
        const auto fails = [](const json &r, const std::vector<std::string> &needles)
        { expectErrorMentions([&] { renderSvg(r, SvgOptions(), "rec.json"); }, needles); };
        fails(broken([](json &s) { s["objects"]["radius"] = "x"; }), {"rec.json", "scene.objects.radius", "\"x\""});
        fails(broken([](json &s) { s["objects"]["height"] = -1; }), {"scene.objects.height", "> 0"});
        fails(broken([](json &s) { s["objects"]["labels"][1] = "can7"; }),
              {"scene.objects.labels[1]", "can7", "not one of the recording's labels"});
        fails(broken([](json &s) { s["objects"]["holder"] = "hand"; }), {"scene.objects.holder", "hand"});
        fails(broken([](json &s) { s["objects"]["grasp_event"] = 3; }), {"scene.objects.grasp_event", "string"});
        fails(broken([](json &s) { s["objects"] = json::array({"can0"}); }), {"scene.objects", "labels"});
        fails(broken([](json &s) { s["reserved_slot"] = 2; }), {"scene.reserved_slot", "2 slots"});
        fails(broken([](json &s) { s["slots"] = "left"; }), {"scene.slots", "array"});
        SvgOptions late;
        late.armSteps = {9};
        expectErrorMentions([&] { renderSvg(shelfRecording(), late, "rec.json"); }, {"step 9", "6 recorded steps"});
        json badEvent = shelfRecording();
        badEvent["events"].push_back({{"step", "two"}, {"event", "grasp-can0"}});
        expectErrorMentions([&] { renderSvg(badEvent, SvgOptions(), "rec.json"); }, {"events", "\"two\""});
    }

    // Shelf-Move's scene declares its cans, slots and reserved slot, and its grasp/release event names are the
    // ones the scene's prefixes recognise: a can grasped by shelfMoveEvent is drawn held at the end effector.
    TEST(SvgObjects, ShelfMoveSceneAndEventsRender)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        const auto parts = shelfMoveParts();
        const json &scene = parts.scene;
        ASSERT_TRUE(scene.contains("objects"));
        EXPECT_EQ(scene["objects"]["labels"], json({"can0", "can1", "can2", "can3"}));
        EXPECT_EQ(scene["objects"]["holder"], "end_effector");
        EXPECT_DOUBLE_EQ(scene["objects"]["height"].get<double>(), parts.model->config().canLength);
        EXPECT_EQ(scene["slots"].size(), parts.model->config().slots.size());
        EXPECT_EQ(scene["reserved_slot"], parts.model->config().reservedSlot);
        EXPECT_FALSE(scene.contains("observation_zones")) << "the slots are not observation zones";

        ShelfMoveModel::State s = parts.model->trueInitialState();
        json r;
        r["scenario"] = parts.name;
        r["labels"] = parts.pointLabels;
        r["scene"] = scene;
        r["trajectory"] = json::array();
        r["events"] = json::array();
        for (int t = 0; t < 3; ++t)
        {
            if (t == 1)
            {
                s.event = ShelfEvent::Grasped;
                s.eventCan = 2;
            }
            else if (t == 2)
            {
                s.event = ShelfEvent::Released;
                s.eventSlot = 3;
            }
            std::vector<Point3> points;
            parts.points(s, points);
            json frame = json::array();
            for (const auto &q : points)
                frame.push_back({q[0], q[1], q[2]});
            r["trajectory"].push_back(frame);
            if (t > 0)
                r["events"].push_back({{"step", t}, {"event", parts.event(s)}});
        }
        EXPECT_EQ(r["events"][0]["event"], "grasp-can2");
        EXPECT_EQ(r["events"][1]["event"], "release-can2-slot3");
        Picture p;
        ASSERT_NO_FATAL_FAILURE(render(r, SvgOptions(), p));
        ASSERT_NE(p.side, nullptr);
        const auto held = withClass(findById(p.top, "objects"), "can held");
        ASSERT_EQ(held.size(), 1u);
        EXPECT_STREQ(held[0]->Attribute("data-label"), "can2");
        EXPECT_EQ(held[0]->IntAttribute("data-step"), 1);
        EXPECT_EQ(cans(findById(p.top, "objects")).size(), 3u * 4u);
        EXPECT_EQ(withClass(findById(p.top, "slots"), "slot reserved").size(), 1u);
    }
}  // namespace ropras::scenarios::test
