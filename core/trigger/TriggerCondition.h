// A start condition on one channel or derived quantity, as the operator
// writes it (`record --trigger`, the GUI's Session ▸ Trigger…), in SI units:
//   a>20e-6          level: while the value is above 20 µε
//   force<0.001      level: while below
//   a rising 20e-6   edge: the sample the value goes from ≤ to above
//   a falling 0      edge: from ≥ to below
//   force inside 0.001..0.002    window: while within, ends included
//   force outside -1e-5..1e-5    window: while beyond either end
// A level or window holds for a stretch (a session's post time counts from
// its end); an edge holds at one sample (post time counts from it).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace tactiscope::core::trigger {

enum class TriggerKind { Above, Below, Rising, Falling, Inside, Outside };

struct TriggerCondition {
    std::string quantity;  // a channel's name or a mode's quantity ("force")
    TriggerKind kind = TriggerKind::Above;
    double level = 0.0;  // Above, Below, Rising, Falling; the window's low end
    double high = 0.0;   // Inside, Outside: the window's high end

    bool isEdge() const { return kind == TriggerKind::Rising || kind == TriggerKind::Falling; }
    // Whether `value` meets a level or window condition (an edge: whether it
    // is past the level in the edge's direction). NaN meets nothing.
    bool holds(double value) const;
    // Whether the step from `previous` to `value` is the edge (levels and
    // windows: whether the condition begins there).
    bool begins(std::optional<double> previous, double value) const;
    std::string text() const;  // back in the form above
    // As people read it, its levels written by `level` in `unit` ("a above
    // 20 µε", "force inside 1..2 mN", "a rising through 0 µε").
    std::string readableText(const std::function<std::string(double)>& level, const std::string& unit) const;
};

// The condition in `text`, or why it is none: "a>20e-6", "a rising 2e-5",
// "force inside 0.001..0.002", … (numbers finite, a window's ends in
// order, a quantity named).
struct ParsedTrigger {
    std::optional<TriggerCondition> condition;
    std::string error;
};
ParsedTrigger parseTrigger(std::string_view text);

}  // namespace tactiscope::core::trigger
