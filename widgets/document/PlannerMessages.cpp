#include "document/PlannerMessages.h"

#include "document/PlannerMessageForms.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>
#include <vector>

namespace fc::ui {

namespace {

using messages::MessageForm;

// Not named tr(): lupdate would file the strings under the enclosing namespace. The texts
// are marked with QT_TRANSLATE_NOOP in the "PlannerMessages" context instead.
QString translated(const char* text) {
    return QCoreApplication::translate("PlannerMessages", text);
}

// A pattern compiled at once: later matches only read it, from any thread (training reports
// its errors from a worker).
QRegularExpression compiled(const QString& pattern) {
    QRegularExpression expression(pattern);
    expression.optimize();
    return expression;
}

// %1, %2... of a sentence replaced in one pass, so that a value holding "%2" (a room's name)
// stays as it is; a translation may put the values in another order.
QString filledIn(const QString& sentence, const QStringList& values) {
    QString out;
    out.reserve(sentence.size());
    for (qsizetype i = 0; i < sentence.size(); ++i) {
        if (sentence[i] == QLatin1Char('%') && i + 1 < sentence.size() &&
            sentence[i + 1].isDigit()) {
            qsizetype end = i + 1;
            int number = 0;
            while (end < sentence.size() && sentence[end].isDigit() && number < 10)
                number = 10 * number + sentence[end++].digitValue();
            if (number >= 1 && number <= values.size()) {
                out += values[number - 1];
                i = end - 1;
                continue;
            }
        }
        out += sentence[i];
    }
    return out;
}

// "boundary", "obstacle 3", "room \"Kitchen\"", "feature 4 (obstacle)"... as the editor
// names them.
QString ringName(const QString& planner) {
    static const QRegularExpression qualified = compiled(QStringLiteral(
        R"re(^(.+) \((?:feature (\d+)|hole (\d+) of the boundary|(boundary|obstacle|room))\)$)re"));
    static const QRegularExpression obstacle = compiled(QStringLiteral(R"re(^obstacle (\d+)$)re"));
    static const QRegularExpression namedRoom = compiled(QStringLiteral(R"re(^room "(.*)"$)re"));
    static const QRegularExpression numberedRoom = compiled(QStringLiteral(R"re(^room (\d+)$)re"));
    static const QRegularExpression feature = compiled(QStringLiteral(R"re(^feature (\d+)$)re"));
    if (const auto m = qualified.match(planner); m.hasMatch()) {
        const QString base = ringName(m.captured(1));
        if (!m.captured(2).isEmpty())
            return filledIn(translated(QT_TRANSLATE_NOOP("PlannerMessages", "%1 (feature %2)")),
                            {base, m.captured(2)});
        if (!m.captured(3).isEmpty())
            return filledIn(
                translated(QT_TRANSLATE_NOOP("PlannerMessages", "%1 (hole %2 in the outer wall)")),
                {base, m.captured(3)});
        const QString role = m.captured(4);
        const char* sentence = role == QLatin1String("boundary")
                                   ? QT_TRANSLATE_NOOP("PlannerMessages", "%1 (outer wall)")
                                   : (role == QLatin1String("obstacle")
                                          ? QT_TRANSLATE_NOOP("PlannerMessages", "%1 (obstacle)")
                                          : QT_TRANSLATE_NOOP("PlannerMessages", "%1 (room)"));
        return filledIn(translated(sentence), {base});
    }
    if (planner == QLatin1String("boundary"))
        return translated(QT_TRANSLATE_NOOP("PlannerMessages", "The outer wall"));
    if (planner == QLatin1String("room"))
        return translated(QT_TRANSLATE_NOOP("PlannerMessages", "A room"));
    if (planner == QLatin1String("an unnamed room"))
        return translated(QT_TRANSLATE_NOOP("PlannerMessages", "An unnamed room"));
    if (const auto m = obstacle.match(planner); m.hasMatch())
        return filledIn(translated(QT_TRANSLATE_NOOP("PlannerMessages", "Obstacle %1")),
                        {m.captured(1)});
    if (const auto m = namedRoom.match(planner); m.hasMatch())
        return filledIn(translated(QT_TRANSLATE_NOOP("PlannerMessages", "Room “%1”")),
                        {m.captured(1)});
    if (const auto m = numberedRoom.match(planner); m.hasMatch())
        return filledIn(translated(QT_TRANSLATE_NOOP("PlannerMessages", "Room %1")),
                        {m.captured(1)});
    if (const auto m = feature.match(planner); m.hasMatch())
        return filledIn(translated(QT_TRANSLATE_NOOP("PlannerMessages", "Feature %1")),
                        {m.captured(1)});
    return planner;
}

const std::vector<MessageForm>& forms() {
    static const std::vector<MessageForm> table = [] {
        // The 3D model's forms first: "room \"A\" left out: room \"A\" lies outside the
        // boundary" holds a plan check that would otherwise match the whole message.
        std::vector<MessageForm> all = messages::modelMessageForms();
        const auto append = [&all](std::vector<MessageForm> more) {
            all.insert(all.end(), std::make_move_iterator(more.begin()),
                       std::make_move_iterator(more.end()));
        };
        append(messages::planningMessageForms());
        append(messages::fileMessageForms());
        for (const MessageForm& form : all) {
            form.pattern.optimize(); // compiled once, before any thread matches
            if (!form.pattern.isValid())
                qWarning("planner message form %s: %s", qPrintable(form.pattern.pattern()),
                         qPrintable(form.pattern.errorString()));
        }
        return all;
    }();
    return table;
}

// A message after the file it is about: "/plans/office.geojson: feature 3 has no geometry".
// The path has a folder separator (or is a Qt resource, or a bare file name with an
// extension) and ends before the first ": ".
const QRegularExpression& filePrefix() {
    static const QRegularExpression pattern = compiled(QStringLiteral(
        R"re(^(?<path>(?:[A-Za-z]:)?[^:]*[/\\][^:]*\S|:/[^:]*\S|[^\s:/\\]+\.\w{1,8}))re"
        R"re(: (?<message>.+)$)re"));
    return pattern;
}

} // namespace

QString plainMessage(const QString& message) {
    for (const MessageForm& form : forms()) {
        const QRegularExpressionMatch m = form.pattern.match(message);
        if (!m.hasMatch())
            continue;
        const QStringList names = form.pattern.namedCaptureGroups();
        QStringList values;
        for (int i = 1; i <= form.pattern.captureCount(); ++i) {
            QString value = m.captured(i);
            if (i < names.size() && names[i] == QLatin1String("ring"))
                value = ringName(value);
            else if (i < names.size() && names[i] == QLatin1String("message"))
                value = plainMessage(value);
            values << value;
        }
        return filledIn(translated(form.sentence), values);
    }
    // The file's path stays; what is said about the file is reworded.
    if (const auto m = filePrefix().match(message); m.hasMatch()) {
        const QString said = m.captured(QStringLiteral("message"));
        const QString plain = plainMessage(said);
        if (plain != said)
            return filledIn(translated(QT_TRANSLATE_NOOP("PlannerMessages", "%1: %2")),
                            {m.captured(QStringLiteral("path")), plain});
    }
    return message;
}

} // namespace fc::ui
