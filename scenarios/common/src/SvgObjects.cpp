#include "SvgObjects.h"

#include <algorithm>
#include <cmath>

namespace ropras::scenarios::detail
{
    namespace
    {
        std::size_t labelIndex(const Recording &rec, const nlohmann::json &j, const std::string &key, const Reader &r)
        {
            if (!j.is_string())
            {
                r.fail(key, "must be a label (a string), not " + Reader::clip(j));
            }
            const auto it = std::find(rec.labels.begin(), rec.labels.end(), j.get<std::string>());
            if (it == rec.labels.end())
            {
                r.fail(key, "names \"" + j.get<std::string>() + "\", which is not one of the recording's labels");
            }
            return std::size_t(it - rec.labels.begin());
        }

        /// whether one of the '+'-joined parts of \a event is \a name or starts with \a name followed by '-'
        bool eventNames(const std::string &event, const std::string &name)
        {
            std::size_t begin = 0;
            while (begin <= event.size())
            {
                const std::size_t end = std::min(event.find('+', begin), event.size());
                const std::string part = event.substr(begin, end - begin);
                if (part == name ||
                    (part.size() > name.size() && part.compare(0, name.size(), name) == 0 && part[name.size()] == '-'))
                {
                    return true;
                }
                begin = end + 1;
            }
            return false;
        }

        /// per step, whether label \a name is held: from its grasp event's step until its release event's step
        std::vector<bool> heldSteps(const Recording &rec, const std::string &grasp, const std::string &release,
                                    const std::string &name, const Reader &r)
        {
            const std::size_t frames = rec.paths.front().size();
            std::vector<bool> held(frames, false);
            if (grasp.empty() || !rec.json->contains("events"))
            {
                return held;
            }
            std::vector<std::pair<std::size_t, bool>> changes;  // step, held after it
            for (const auto &e : (*rec.json)["events"])
            {
                if (!e.is_object() || !e.contains("step") || !e["step"].is_number_integer() ||
                    e["step"].get<long>() < 0 || !e.contains("event") || !e["event"].is_string())
                {
                    r.fail("events", "must hold {\"step\": n, \"event\": name} entries, not " + Reader::clip(e));
                }
                const std::string event = e["event"].get<std::string>();
                if (eventNames(event, grasp + name))
                    changes.emplace_back(e["step"].get<std::size_t>(), true);
                else if (!release.empty() && eventNames(event, release + name))
                    changes.emplace_back(e["step"].get<std::size_t>(), false);
            }
            std::stable_sort(changes.begin(), changes.end(),
                             [](const auto &a, const auto &b) { return a.first < b.first; });
            bool now = false;
            std::size_t next = 0;
            for (std::size_t t = 0; t < frames; ++t)
            {
                while (next < changes.size() && changes[next].first <= t)
                    now = changes[next++].second;
                held[t] = now;
            }
            return held;
        }

        std::vector<std::size_t> drawnSteps(std::size_t frames, const std::vector<std::size_t> &chosen, const Reader &r)
        {
            for (const std::size_t s : chosen)
            {
                if (s >= frames)
                {
                    r.fail("step " + std::to_string(s),
                           "is past the trajectory's end (" + std::to_string(frames) + " recorded steps)");
                }
            }
            if (!chosen.empty())
                return chosen;
            std::vector<std::size_t> steps;
            const std::size_t n = std::min<std::size_t>(6, frames);
            for (std::size_t i = 0; i < n; ++i)
            {
                const std::size_t s = n > 1 ? i * (frames - 1) / (n - 1) : 0;
                if (steps.empty() || steps.back() != s)
                    steps.push_back(s);
            }
            return steps;
        }

        double positive(const nlohmann::json &j, const std::string &key, const Reader &r)
        {
            const double v = r.number(j, key);
            if (!(v > 0.0))
                r.fail(key, "must be > 0");
            return v;
        }

        /// a circle of radius \a radius (top view) or a radius x height rectangle (side view) centred at \a c
        void body(std::ostringstream &svg, const SvgFrame &f, const Vec &c, double radius, double height,
                  const std::string &attributes)
        {
            if (f.v == 1)
            {
                svg << "<circle cx=\"" << num(f.x(c[f.u])) << "\" cy=\"" << num(f.y(c[f.v])) << "\" r=\""
                    << num(std::max(1.0, radius * f.scale)) << "\" " << attributes << "/>\n";
                return;
            }
            svg << "<rect x=\"" << num(f.x(c[f.u] - radius)) << "\" y=\"" << num(f.y(c[f.v] + 0.5 * height))
                << "\" width=\"" << num(std::max(1.0, 2.0 * radius * f.scale)) << "\" height=\""
                << num(std::max(1.0, height * f.scale)) << "\" " << attributes << "/>\n";
        }
    }  // namespace

    SceneObjects readSceneObjects(const Recording &rec, const std::vector<std::size_t> &chosen, const Reader &r)
    {
        SceneObjects out;
        const nlohmann::json &scene = *rec.scene;
        if (scene.contains("objects"))
        {
            const auto &o = scene["objects"];
            if (!o.is_object() || !o.contains("labels") || !o["labels"].is_array())
            {
                r.fail("scene.objects",
                       "must be {\"labels\": [...], \"radius\": r, \"height\": h, ...}, not " + Reader::clip(o));
            }
            out.radius = positive(o.value("radius", nlohmann::json()), "scene.objects.radius", r);
            out.height = positive(o.value("height", nlohmann::json()), "scene.objects.height", r);
            const auto text = [&](const char *key)
            {
                if (!o.contains(key))
                    return std::string();
                if (!o[key].is_string())
                    r.fail(std::string("scene.objects.") + key, "must be a string, not " + Reader::clip(o[key]));
                return o[key].get<std::string>();
            };
            if (o.contains("holder"))
                out.holder = long(labelIndex(rec, o["holder"], "scene.objects.holder", r));
            for (std::size_t i = 0; i < o["labels"].size(); ++i)
            {
                const std::size_t k =
                    labelIndex(rec, o["labels"][i], "scene.objects.labels[" + std::to_string(i) + "]", r);
                out.labels.push_back(k);
                out.held.push_back(heldSteps(rec, text("grasp_event"), text("release_event"), rec.labels[k], r));
            }
        }
        if (scene.contains("slots"))
        {
            out.slots = r.shapes(scene["slots"], "scene.slots");
            if (scene.contains("reserved_slot"))
            {
                const auto &j = scene["reserved_slot"];
                if (!j.is_number_integer() || j.get<long>() < 0 || j.get<long>() >= long(out.slots.size()))
                {
                    r.fail("scene.reserved_slot", "must be an index into scene.slots (" +
                                                      std::to_string(out.slots.size()) + " slots), not " +
                                                      Reader::clip(j));
                }
                out.reserved = j.get<long>();
            }
        }
        if (!out.labels.empty())
            out.steps = drawnSteps(rec.paths.front().size(), chosen, r);
        return out;
    }

    std::string objectColour(std::size_t k)
    {
        static const char *palette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
        return palette[k % (sizeof(palette) / sizeof(palette[0]))];
    }

    bool isObjectLabel(const SceneObjects &objects, std::size_t label)
    {
        return std::find(objects.labels.begin(), objects.labels.end(), label) != objects.labels.end();
    }

    void drawObjects(std::ostringstream &svg, const SvgFrame &f, const SceneObjects &objects, const Recording &rec,
                     bool main)
    {
        const auto group = [&](const char *id)
        { return main ? std::string("<g id=\"") + id + "\">\n" : std::string("<g class=\"") + id + "\">\n"; };
        if (!objects.slots.empty())
        {
            svg << group("slots");
            // the reserved slot last, so that a slot it overlaps (the same x in the side view) does not cover it
            std::vector<std::size_t> order;
            for (std::size_t i = 0; i < objects.slots.size(); ++i)
            {
                if (long(i) != objects.reserved)
                    order.push_back(i);
            }
            if (objects.reserved >= 0)
                order.push_back(std::size_t(objects.reserved));
            for (const std::size_t i : order)
            {
                const Shape &s = objects.slots[i];
                const bool reserved = long(i) == objects.reserved;
                const double radius = objects.radius > 0.0 ? objects.radius : std::max(s.radius, 0.01);
                const double height = objects.height > 0.0 ? objects.height : 2.0 * radius;
                body(svg, f, s.lo, radius, height,
                     std::string("class=\"slot") + (reserved ? " reserved" : "") + "\" data-slot=\"" +
                         std::to_string(i) + "\" fill=\"none\" stroke=\"" + (reserved ? "#2e7d32" : "#777777") +
                         "\" stroke-width=\"" + (reserved ? "2.5" : "1") + "\" stroke-dasharray=\"" +
                         (reserved ? "none" : "3 2") + "\"");
            }
            svg << "</g>\n";
        }
        if (objects.labels.empty())
            return;
        svg << group("objects");
        for (const std::size_t step : objects.steps)
        {
            const double late = objects.steps.size() > 1 ? double(step) / double(objects.steps.back()) : 1.0;
            svg << "<g class=\"object-step\" data-step=\"" << step << "\">\n";
            for (std::size_t i = 0; i < objects.labels.size(); ++i)
            {
                const std::size_t k = objects.labels[i];
                const bool held = objects.held[i][step];
                const std::string colour = objectColour(i);
                const std::size_t at = held && objects.holder >= 0 ? std::size_t(objects.holder) : k;
                body(svg, f, rec.paths[at][step], objects.radius, objects.height,
                     std::string("class=\"can") + (held ? " held" : "") + "\" data-label=\"" +
                         xmlEscape(rec.labels[k]) + "\" data-step=\"" + std::to_string(step) + "\" fill=\"" +
                         (held ? "none" : colour) + "\" fill-opacity=\"" + num(0.08 + 0.2 * late) + "\" stroke=\"" +
                         colour + "\" stroke-width=\"" + (held ? "2.5" : "1") + "\"" +
                         (held ? " stroke-dasharray=\"4 2\"" : ""));
            }
            svg << "</g>\n";
        }
        svg << "</g>\n";
    }

    void drawObjectBeliefs(std::ostringstream &svg, const SvgFrame &f, const SceneObjects &objects,
                           const Recording &rec, const std::vector<const RecordedBelief *> &beliefs, bool main)
    {
        if (objects.labels.empty() || beliefs.empty())
            return;
        svg << (main ? "<g id=\"object_beliefs\">\n" : "<g class=\"object_beliefs\">\n");
        for (std::size_t i = 0; i < objects.labels.size(); ++i)
        {
            const std::size_t k = objects.labels[i];
            svg << "<g data-label=\"" << xmlEscape(rec.labels[k]) << "\" fill=\"" << objectColour(i) << "\">\n";
            for (const auto *belief : beliefs)
            {
                for (const auto &particle : belief->particles)
                {
                    const Vec &q = particle[k];
                    svg << "<circle class=\"particle object-particle\" data-step=\"" << belief->step << "\" cx=\""
                        << num(f.x(q[f.u])) << "\" cy=\"" << num(f.y(q[f.v]))
                        << "\" r=\"1.6\" fill-opacity=\"0.5\"/>\n";
                }
            }
            svg << "</g>\n";
        }
        svg << "</g>\n";
    }

    std::vector<LegendEntry> objectLegend(const SceneObjects &objects, const Recording &rec, bool beliefs)
    {
        std::vector<LegendEntry> legend;
        for (std::size_t i = 0; i < objects.labels.size(); ++i)
        {
            legend.push_back(
                {rec.labels[objects.labels[i]] + (beliefs ? " (body and belief particles)" : ""), objectColour(i)});
        }
        if (!objects.labels.empty())
            legend.push_back({"held object: dashed outline at the hand", "#000000"});
        if (!objects.slots.empty())
            legend.push_back({"slots (dashed)", "#777777"});
        if (objects.reserved >= 0)
            legend.push_back({"reserved slot (bold)", "#2e7d32"});
        return legend;
    }
}  // namespace ropras::scenarios::detail
