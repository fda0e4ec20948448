#include "model/workcontextjson.h"

#include <QCoreApplication>

namespace tipscope::model {

namespace {
struct WorkContextJsonTr {
    Q_DECLARE_TR_FUNCTIONS(WorkContextJson)
};

const QString kWorkOrder = QStringLiteral("work_order");
const QString kSerial = QStringLiteral("board_serial");
const QString kOperator = QStringLiteral("operator");
} // namespace

QJsonObject workContextToJson(const WorkContext &context) {
    return {{kWorkOrder, context.workOrder},
            {kSerial, context.boardSerial},
            {kOperator, context.operatorName}};
}

protocol::Outcome<WorkContext> workContextFromJson(const QJsonObject &json) {
    for (const QString &key : {kWorkOrder, kSerial, kOperator})
        if (json.contains(key) && !json.value(key).isString())
            return protocol::failure(WorkContextJsonTr::tr("%1 must be text").arg(key));
    return WorkContext{json.value(kWorkOrder).toString().trimmed(),
                       json.value(kSerial).toString().trimmed(),
                       json.value(kOperator).toString().trimmed()};
}

} // namespace tipscope::model
