<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
    <context>
        <name>@default</name>
        <message>
            <source>terrain (hillshade)</source>
            <translation>التضاريس (تظليل)</translation>
        </message>
        <message>
            <source>nodata</source>
            <translation>بلا بيانات</translation>
        </message>
        <message>
            <source>Legend</source>
            <translation>مفتاح الرموز</translation>
        </message>
        <message>
            <source>Hillshade</source>
            <translation>تظليل التضاريس</translation>
        </message>
        <message>
            <source>not used (outside / nodata)</source>
            <translation>غير مستخدمة (خارج / بلا بيانات)</translation>
        </message>
        <message>
            <source>Error DTM − check (m)</source>
            <translation>الخطأ = النموذج − نقطة التحقق (م)</translation>
        </message>
        <message>
            <source>Residual map</source>
            <translation>خريطة البواقي</translation>
        </message>
        <message>
            <source>check height (m)</source>
            <translation>ارتفاع نقطة التحقق (م)</translation>
        </message>
        <message>
            <source>error DTM − check (m)</source>
            <translation>الخطأ = النموذج − نقطة التحقق (م)</translation>
        </message>
        <message>
            <source>zero error</source>
            <translation>خطأ صفري</translation>
        </message>
        <message>
            <source>Error against height</source>
            <translation>الخطأ مقابل الارتفاع</translation>
        </message>
        <message>
            <source>no point</source>
            <translation>لا نقاط</translation>
        </message>
        <message>
            <source>Class map</source>
            <translation>خريطة الأصناف</translation>
        </message>
        <message>
            <source>ASPRS class</source>
            <translation>صنف ASPRS</translation>
        </message>
        <message>
            <source>Error map</source>
            <translation>خريطة الأخطاء</translation>
        </message>
        <message>
            <source>Filter error</source>
            <translation>خطأ المرشِّح</translation>
        </message>
        <message>
            <source>Tile map</source>
            <translation>خريطة البلاطات</translation>
        </message>
        <message>
            <source>Tile status</source>
            <translation>حالة البلاطة</translation>
        </message>
        <message>
            <source>Slope threshold θ (degrees)</source>
            <translation>عتبة الميل θ (درجة)</translation>
        </message>
        <message>
            <source>Percent (%)</source>
            <translation>النسبة المئوية (%)</translation>
        </message>
        <message>
            <source>best threshold</source>
            <translation>أفضل عتبة</translation>
        </message>
        <message>
            <source>Errors against the slope threshold</source>
            <translation>الأخطاء مقابل عتبة الميل</translation>
        </message>
        <message>
            <source>fast</source>
            <translation>سريعة</translation>
        </message>
        <message>
            <source>slow</source>
            <translation>بطيئة</translation>
        </message>
        <message>
            <source>finished earlier</source>
            <translation>انتهت سابقاً</translation>
        </message>
        <message>
            <source>failed</source>
            <translation>فشلت</translation>
        </message>
        <message>
            <source>check-point RMS_T</source>
            <translation>RMS_T نقاط التحقق</translation>
        </message>
        <message>
            <source>map X</source>
            <translation>X الخريطة</translation>
        </message>
        <message>
            <source>map Y</source>
            <translation>Y الخريطة</translation>
        </message>
    </context>
    <context>
        <name>BuildingsAlgorithm</name>
        <message>
            <source>Building footprints with heights</source>
            <translation>مساقط المباني مع ارتفاعاتها</translation>
        </message>
        <message>
            <source>Roof planes found by region growing above the DTM, as footprints with height, area, volume, storeys and roof type.</source>
            <translation>مستويات الأسطح المستخرجة بتنمية المناطق فوق نموذج التضاريس، كمساقط مع الارتفاع والمساحة والحجم والطوابق ونوع السطح.</translation>
        </message>
        <message>
            <source>buildings,footprints,roofs,lod1,extraction,height,volume,storeys,class 6,lidar</source>
            <translation>مبانٍ,مساقط,أسطح,lod1,استخراج,ارتفاع,حجم,طوابق,الصنف 6,ليدار</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Ground classes</source>
            <translation>أصناف الأرض</translation>
        </message>
        <message>
            <source>Minimum height above ground (m)</source>
            <translation>أدنى ارتفاع فوق الأرض (م)</translation>
        </message>
        <message>
            <source>Maximum angle between roof normals (°)</source>
            <translation>أقصى زاوية بين نواظم الأسطح (°)</translation>
        </message>
        <message>
            <source>Minimum roof patch area (m²)</source>
            <translation>أدنى مساحة لرقعة السطح (م²)</translation>
        </message>
        <message>
            <source>Minimum building area (m²)</source>
            <translation>أدنى مساحة للمبنى (م²)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>حجم الخلية (م)</translation>
        </message>
        <message>
            <source>Building footprints</source>
            <translation>مساقط المباني</translation>
        </message>
        <message>
            <source>Classified cloud (class 6 = building)</source>
            <translation>السحابة المصنّفة (الصنف 6 = مبنى)</translation>
        </message>
        <message>
            <source>Ground in class 2 (run a ground filter first), in a projected CRS (metres).</source>
            <translation>الأرض في الفئة 2 (شغّل مرشح أرض أولًا)، بنظام إحداثيات مُسقَط (بالأمتار).</translation>
        </message>
        <message>
            <source>The specification gives 1.5–2 m.</source>
            <translation>تحدّد المواصفة 1.5–2 m.</translation>
        </message>
        <message>
            <source>GeoPackage polygons with height, area, volume, storeys, roof type, ground and roof heights.</source>
            <translation>مضلعات GeoPackage بالارتفاع والمساحة والحجم وعدد الطوابق ونوع السقف وارتفاعَي الأرض والسقف.</translation>
        </message>
        <message>
            <source>Building footprints report</source>
            <translation>تقرير مساقط المباني</translation>
        </message>
        <message>
            <source>Buildings</source>
            <translation>المباني</translation>
        </message>
        <message>
            <source>Total footprint area (m²)</source>
            <translation>إجمالي مساحة المساقط (م²)</translation>
        </message>
        <message>
            <source>Total volume (m³)</source>
            <translation>الحجم الإجمالي (م³)</translation>
        </message>
        <message>
            <source>Extracts buildings from a ground-classified LAS/LAZ cloud: points above the ground TIN are fitted with local planes, and neighbours with agreeing normals grow into roof patches; trees are rejected because their points are not planar. Each footprint gets a roof model fitted to its roof points only (flat, shed, gabled, hipped or complex), so canopy over a roof does not raise it; heights, eave heights, area, volume and storeys follow from it. A deck whose surface runs on into the ground at both ends (a bridge) is not a building. Optional LOD1/LOD2 CityJSON and OBJ 3D models. Clouds in feet are converted: heights, areas and volumes are in metres, geometry in the data's CRS.</source>
            <translation>يستخرج المباني من سحابة LAS/LAZ مصنّفة الأرض: تُطابَق النقاط الواقعة فوق شبكة TIN للأرض بمستويات محلية، وتنمو النقاط المتجاورة ذات المتجهات العمودية المتوافقة إلى رقع أسطح؛ وتُرفض الأشجار لأن نقاطها غير مستوية. يحصل كل مسقط على نموذج سقف مطابَق على نقاط سقفه فقط (مسطّح، أحادي الميل، جملوني، هرمي أو معقّد)، فلا ترفعه الأشجار المتدلية فوقه؛ ومنه تُشتق الارتفاعات وارتفاعات الأفاريز والمساحة والحجم والطوابق. السطح الذي يمتد حتى الأرض عند طرفيه (جسر) ليس مبنى. نماذج ثلاثية الأبعاد اختيارية LOD1/LOD2 بصيغة CityJSON وOBJ. تُحوَّل السحب بالقدم: الارتفاعات والمساحات والأحجام بالمتر، والهندسة في نظام إحداثيات البيانات.</translation>
        </message>
        <message>
            <source>Storeys = mean roof height above ground / this height (the specification gives 2.5–3.5 m).</source>
            <translation>الطوابق = متوسط ارتفاع السقف فوق الأرض ÷ هذا الارتفاع (تعطي المواصفة 2.5–3.5 م).</translation>
        </message>
        <message>
            <source>CityJSON 2.0: each building as an LOD1 block and, for rectangular footprints with a flat, shed, gabled or hipped roof, an LOD2 solid with roof, wall and ground surfaces.</source>
            <translation>CityJSON 2.0: كل مبنى ككتلة LOD1، وللمساقط المستطيلة ذات السطح المسطّح أو أحادي الميل أو الجملوني أو الهرمي مجسّم LOD2 بأسطح السقف والجدران والأرضية.</translation>
        </message>
        <message>
            <source>Storey height (m)</source>
            <translation>ارتفاع الطابق (م)</translation>
        </message>
        <message>
            <source>3D city model (CityJSON, LOD1 and LOD2)</source>
            <translation>نموذج المدينة ثلاثي الأبعاد (CityJSON، LOD1 وLOD2)</translation>
        </message>
        <message>
            <source>3D model for viewers (OBJ)</source>
            <translation>نموذج ثلاثي الأبعاد للعارضات (OBJ)</translation>
        </message>
        <message>
            <source>{} buildings; data units (horizontal / vertical): {}</source>
            <translation>{} مبانٍ؛ وحدات البيانات (أفقية / رأسية): {}</translation>
        </message>
    </context>
    <context>
        <name>CatalogAlgorithm</name>
        <message>
            <source>Process a LiDAR tile catalog</source>
            <translation>معالجة فهرس بلاطات ليدار</translation>
        </message>
        <message>
            <source>Ground filter and DTM over a whole folder of LAS/LAZ tiles, in parallel, without seams.</source>
            <translation>مرشح الأرض ونموذج التضاريس الرقمي لمجلد كامل من بلاطات LAS/LAZ، بالتوازي ودون فواصل.</translation>
        </message>
        <message>
            <source>Keep the classes already in the files</source>
            <translation>الإبقاء على الأصناف الموجودة في الملفات</translation>
        </message>
        <message>
            <source>LSQ surfaces, faithful (the paper)</source>
            <translation>أسطح المربعات الصغرى، مطابقة (الورقة)</translation>
        </message>
        <message>
            <source>LSQ surfaces, improved (ours)</source>
            <translation>أسطح المربعات الصغرى، محسّنة (نسختنا)</translation>
        </message>
        <message>
            <source>Slope filter, exact (Vosselman 2000)</source>
            <translation>مرشح الميل، دقيق (Vosselman 2000)</translation>
        </message>
        <message>
            <source>Slope filter, terrain-adaptive</source>
            <translation>مرشح الميل، متكيّف مع التضاريس</translation>
        </message>
        <message>
            <source>IDW</source>
            <translation>IDW</translation>
        </message>
        <message>
            <source>Kriging</source>
            <translation>الكريغينغ</translation>
        </message>
        <message>
            <source>TIN</source>
            <translation>TIN</translation>
        </message>
        <message>
            <source>Ground filter</source>
            <translation>مرشح الأرض</translation>
        </message>
        <message>
            <source>DTM method</source>
            <translation>طريقة نموذج التضاريس</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>حجم خلية نموذج التضاريس (م)</translation>
        </message>
        <message>
            <source>Buffer around each tile (m)</source>
            <translation>الهامش حول كل بلاطة (م)</translation>
        </message>
        <message>
            <source>Worker processes (0 = one per core)</source>
            <translation>العمليات العاملة (0 = واحدة لكل نواة)</translation>
        </message>
        <message>
            <source>Dask scheduler address (empty = local)</source>
            <translation>عنوان مجدول Dask (فارغ = محلي)</translation>
        </message>
        <message>
            <source>Also write one Cloud-Optimized GeoTIFF</source>
            <translation>كتابة ملف GeoTIFF واحد محسَّن للسحابة أيضاً</translation>
        </message>
        <message>
            <source>Output folder</source>
            <translation>مجلد النواتج</translation>
        </message>
        <message>
            <source>Tiles</source>
            <translation>البلاطات</translation>
        </message>
        <message>
            <source>Failed tiles</source>
            <translation>البلاطات الفاشلة</translation>
        </message>
        <message>
            <source>Points per second</source>
            <translation>نقطة في الثانية</translation>
        </message>
        <message>
            <source>Tile {0} failed: {1}</source>
            <translation>فشلت البلاطة {0}: {1}</translation>
        </message>
        <message>
            <source>Ground filter (recommended)</source>
            <translation>مرشح الأرض (الموصى به)</translation>
        </message>
        <message>
            <source>Classifies ground and builds a DTM for every tile of a LiDAR project, each tile read with a buffer of its neighbours' points so that results have no seams. Tiles run in parallel on Dask, locally or on a cluster; a rerun skips finished tiles.</source>
            <translation>يصنّف الأرض ويبني نموذج تضاريس رقميًا لكل بلاطة في مشروع LiDAR، وتُقرأ كل بلاطة مع نطاق عازل من نقاط جيرانها فلا تظهر خطوط التقاء في النتائج. تعمل البلاطات بالتوازي على Dask محليًا أو على عنقود؛ وإعادة التشغيل تتخطى البلاطات المنجزة.</translation>
        </message>
        <message>
            <source>The first choice keeps the classes already in the files.</source>
            <translation>الخيار الأول يُبقي الفئات الموجودة في الملفات.</translation>
        </message>
        <message>
            <source>e.g. tcp://host:8786.</source>
            <translation>مثل tcp://host:8786.</translation>
        </message>
        <message>
            <source>Must not hold the input tiles; receives the classified tiles, one DTM per tile and a VRT mosaic.</source>
            <translation>يجب ألا يحوي بلاطات الإدخال؛ ويستقبل البلاطات المصنّفة ونموذج تضاريس لكل بلاطة وفسيفساء VRT.</translation>
        </message>
        <message>
            <source>A map of the tiles by status, and time and points per second per worker.</source>
            <translation>خريطة البلاطات حسب حالتها، والزمن وعدد النقاط في الثانية لكل عامل.</translation>
        </message>
        <message>
            <source>Tile catalog report</source>
            <translation>تقرير فهرس البلاطات</translation>
        </message>
        <message>
            <source>0 processes whole tiles; a size (a multiple of the cell size) cuts the catalog into squares read from the tiles they overlap.</source>
            <translation>القيمة 0 تعالج البلاطات كاملة؛ أما الحجم (مضاعف لحجم الخلية) فيقسم الفهرس إلى مربعات تُقرأ من البلاطات التي تتقاطع معها.</translation>
        </message>
        <message>
            <source>Chunk size (m, 0 = the tiles)</source>
            <translation>حجم القطعة (م، 0 = البلاطات)</translation>
        </message>
        <message>
            <source>Must exceed the filter's reach (about 100 m for the recommended filter, 240 m for the improved LSQ, 120 m for the terrain-adaptive slope filter) and the DTM search distance.</source>
            <translation>يجب أن يتجاوز مدى تأثير المرشح (نحو 100 م للمرشح الموصى به، و240 م لـ LSQ المحسّن، و120 م لمرشح الانحدار المتكيف مع التضاريس) ومسافة البحث لنموذج التضاريس الرقمي.</translation>
        </message>
        <message>
            <source>DTM mosaic (VRT)</source>
            <translation>فسيفساء نموذج التضاريس الرقمي (VRT)</translation>
        </message>
        <message>
            <source>Tiles: LAS/LAZ files, folders or a .vpc</source>
            <translation>البلاطات: ملفات LAS/LAZ أو مجلدات أو ملف ‎.vpc</translation>
        </message>
        <message>
            <source>Tile {key}: finished by an earlier run, kept.</source>
            <translation>البلاطة {key}: أُنجزت في تشغيل سابق، أُبقيت.</translation>
        </message>
        <message>
            <source>Tile {key}: no point of its own, no DTM.</source>
            <translation>البلاطة {key}: لا نقاط خاصة بها، لا نموذج تضاريس رقمي.</translation>
        </message>
        <message>
            <source>Tile {key} done: {points} points, {ground} ground, {seconds:.1f} s.</source>
            <translation>أُنجزت البلاطة {key}: {points} نقطة، {ground} أرضية، {seconds:.1f} ث.</translation>
        </message>
        <message>
            <source>Cancelled by the user. {n} finished tile(s) are kept in {folder}: run again with the same settings to resume; unfinished tiles left nothing.</source>
            <translation>ألغاه المستخدم. أُبقيت {n} بلاطة منجزة في {folder}: شغّل مجدداً بالإعدادات نفسها للاستئناف؛ البلاطات غير المنجزة لم تترك شيئاً.</translation>
        </message>
        <message>
            <source>Ground filter (progressive TIN densification)</source>
            <translation>مرشح الأرض (التكثيف التدريجي لشبكة TIN)</translation>
        </message>
        <message>
            <source>Off: a damaged or truncated tile stops the run before anything is written, naming every such tile. On: those tiles are left out (named in the log) and their neighbours get no buffer points from them.</source>
            <translation>معطّل: توقف أي بلاطة تالفة أو مبتورة التشغيل قبل كتابة أي شيء، مع تسمية كل بلاطة من هذا النوع. مفعّل: تُستبعد تلك البلاطات (وتُذكر في السجل) ولا تحصل جاراتها على نقاط حافة منها.</translation>
        </message>
        <message>
            <source>Skip unreadable tiles</source>
            <translation>تخطّي البلاطات غير المقروءة</translation>
        </message>
        <message>
            <source>Tile {path} skipped: {reason}</source>
            <translation>تم تخطّي البلاطة {path}: {reason}</translation>
        </message>
        <message>
            <source>All tiles must share one CRS. Tiles without points are left out; tiles without ground within reach (a lake, the sea) get a nodata DTM. Both are named in the log and the report.</source>
            <translation>يجب أن تشترك كل البلاطات في نظام إحداثيات واحد. تُستبعد البلاطات التي بلا نقاط؛ والبلاطات التي لا أرض على مقربة منها (بحيرة، بحر) يكون نموذج التضاريس الرقمي الخاص بها بلا بيانات. تُذكر كلتاهما في السجل والتقرير.</translation>
        </message>
        <message>
            <source>Cells are nodata where a DTM of all the tiles as one file would leave them empty: farther than five mean ground spacings from ground (TIN: triangles with an edge over twice that), derived from the whole catalog once every tile is done.</source>
            <translation>تكون الخلايا بلا بيانات حيث يتركها نموذج التضاريس الرقمي لكل البلاطات كملف واحد فارغة: أبعد من خمسة أضعاف متوسط التباعد بين نقاط الأرض عن الأرض (في TIN: المثلثات التي يزيد أحد أضلاعها عن ضعف ذلك)، وتُشتق هذه المسافة من الفهرس كله بعد انتهاء كل البلاطات.</translation>
        </message>
        <message>
            <source>Terminated. {n} finished tile(s) are kept in {folder}: run again with the same settings to resume; unfinished tiles left nothing.</source>
            <translation>أُنهي التشغيل. أُبقيت {n} بلاطة منجزة في {folder}: شغّل مجدداً بالإعدادات نفسها للاستئناف؛ البلاطات غير المنجزة لم تترك شيئاً.</translation>
        </message>
        <message>
            <source>{n} tile(s) classified again at the canopy scale of the whole catalog: {keys}.</source>
            <translation>{n} بلاطة (بلاطات) صُنِّفت من جديد بمقياس الغطاء الشجري للفهرس كله: {keys}.</translation>
        </message>
        <message>
            <source>A kept tile whose canopy scale differs from the whole catalog's is classified again by the resume.</source>
            <translation>البلاطة المحفوظة التي يختلف مقياس غطائها الشجري عن مقياس الفهرس كله تُصنَّف من جديد عند الاستئناف.</translation>
        </message>
    </context>
    <context>
        <name>CheckPointInputs</name>
        <message>
            <source>Check points (point layer)</source>
            <translation>نقاط التحقق (طبقة نقطية)</translation>
        </message>
        <message>
            <source>Height field (empty = geometry Z)</source>
            <translation>حقل الارتفاع (فارغ = قيمة Z من الهندسة)</translation>
        </message>
        <message>
            <source>Id field</source>
            <translation>حقل المعرِّف</translation>
        </message>
        <message>
            <source>CRS of the check point file (default: DTM CRS)</source>
            <translation>نظام إحداثيات ملف نقاط التحقق (الافتراضي: نظام إحداثيات DTM)</translation>
        </message>
        <message>
            <source>Reproject check points to the DTM CRS</source>
            <translation>إعادة إسقاط نقاط التحقق إلى نظام إحداثيات DTM</translation>
        </message>
        <message>
            <source>Sampling</source>
            <translation>طريقة الاعتيان</translation>
        </message>
        <message>
            <source>Bilinear</source>
            <translation>ثنائي الخطية</translation>
        </message>
        <message>
            <source>Nearest cell</source>
            <translation>أقرب خلية</translation>
        </message>
        <message>
            <source>Give the check points as a point layer (CHECKPOINTS) or a file (CHECKPOINTS_CSV).</source>
            <translation>حدِّد نقاط التحقق كطبقة نقطية (CHECKPOINTS) أو كملف (CHECKPOINTS_CSV).</translation>
        </message>
        <message>
            <source>Give the check points either as a layer or as a file, not both.</source>
            <translation>حدِّد نقاط التحقق إما كطبقة أو كملف، لا الاثنين معاً.</translation>
        </message>
        <message>
            <source>The check point layer has no Z coordinate; choose the height field (Z_FIELD).</source>
            <translation>طبقة نقاط التحقق لا تحوي الإحداثي Z؛ اختر حقل الارتفاع (Z_FIELD).</translation>
        </message>
        <message>
            <source>The check point layer has no points.</source>
            <translation>طبقة نقاط التحقق لا تحوي أي نقطة.</translation>
        </message>
        <message>
            <source>check point layer</source>
            <translation>طبقة نقاط التحقق</translation>
        </message>
        <message>
            <source>check point file</source>
            <translation>ملف نقاط التحقق</translation>
        </message>
        <message>
            <source>The {} is in {} but the DTM is in {}. Reproject the check points first or tick 'Reproject check points to the DTM CRS' (REPROJECT=true; x, y only, heights are not converted). No output was written.</source>
            <translation>{} بنظام الإحداثيات {} لكن نموذج التضاريس الرقمي بنظام {}. أعد إسقاط نقاط التحقق أولاً أو فعِّل الخيار 'إعادة إسقاط نقاط التحقق إلى نظام إحداثيات DTM' (REPROJECT=true؛ x وy فقط، ولا تُحوَّل الارتفاعات). لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>Check points reprojected from {} to {}</source>
            <translation>أُعيد إسقاط نقاط التحقق من {} إلى {}</translation>
        </message>
        <message>
            <source>Check points assumed to be in the DTM's CRS.</source>
            <translation>افتُرض أن نقاط التحقق بنظام إحداثيات نموذج التضاريس الرقمي.</translation>
        </message>
    </context>
    <context>
        <name>ClassifyAlgorithm</name>
        <message>
            <source>Classify point cloud (ASPRS classes)</source>
            <translation>تصنيف سحابة النقاط (أصناف ASPRS)</translation>
        </message>
        <message>
            <source>Ground, low/medium/high vegetation, buildings and low noise in one run; water and the other attributes kept.</source>
            <translation>الأرض والغطاء النباتي المنخفض/المتوسط/المرتفع والمباني والضوضاء المنخفضة في تشغيل واحد؛ مع الإبقاء على الماء والخصائص الأخرى.</translation>
        </message>
        <message>
            <source>lidar,las,laz,classification,asprs,ground,vegetation,building,noise,water,height above ground,normalize</source>
            <translation>ليدار,las,laz,تصنيف,asprs,أرض,غطاء نباتي,مبنى,ضوضاء,ماء,ارتفاع فوق الأرض,تطبيع</translation>
        </message>
        <message>
            <source>Writes standard ASPRS classes into a copy of a LAS/LAZ cloud: 2 ground (the recommended ground filter, or the input's class 2 kept), 3/4/5 low/medium/high vegetation by height above a TIN of the ground, 6 building (roof planes, bridges refused), 7 low noise; water (9) and noise (18) are kept. Every other attribute, the VLRs and the CRS are copied unchanged. Heights are in metres also for clouds in feet (converted).</source>
            <translation>يكتب أصناف ASPRS القياسية في نسخة من سحابة LAS/LAZ: ‏2 أرض (مرشح الأرض الموصى به، أو الإبقاء على الصنف 2 من المدخل)، ‏3/4/5 غطاء نباتي منخفض/متوسط/مرتفع حسب الارتفاع فوق شبكة TIN للأرض، ‏6 مبنى (مستويات الأسطح، مع رفض الجسور)، ‏7 ضوضاء منخفضة؛ ويُبقي على الماء (9) والضوضاء (18). تُنسخ كل الخصائص الأخرى وسجلات VLR ونظام الإحداثيات دون تغيير. الارتفاعات بالمتر حتى للسحب بالقدم (تُحوَّل).</translation>
        </message>
        <message>
            <source>A .las or .laz file in a projected CRS.</source>
            <translation>ملف .las أو .laz في نظام إحداثيات مُسقَط.</translation>
        </message>
        <message>
            <source>Keep the input's class 2 when it was already filtered.</source>
            <translation>أبقِ على الصنف 2 من المدخل إذا كان قد رُشِّح مسبقًا.</translation>
        </message>
        <message>
            <source>Default 0.5 m and 1.5 m: the IGN LiDAR HD vegetation classes.</source>
            <translation>الافتراضي 0.5 م و1.5 م: أصناف الغطاء النباتي في IGN LiDAR HD.</translation>
        </message>
        <message>
            <source>The specification gives 1.5–2 m.</source>
            <translation>تحدّد المواصفة 1.5–2 m.</translation>
        </message>
        <message>
            <source>Classes 8 and 10–255 (rail, road, wires, bridge decks, vendor classes) keep their class.</source>
            <translation>تحتفظ الأصناف 8 و10–255 (السكك، الطرق، الأسلاك، أسطح الجسور، أصناف المورّد) بصنفها.</translation>
        </message>
        <message>
            <source>A float extra dimension HeightAboveGround in the cloud's vertical unit (as PDAL's filters.hag_delaunay).</source>
            <translation>بُعد إضافي عشري HeightAboveGround بالوحدة الرأسية للسحابة (مثل filters.hag_delaunay في PDAL).</translation>
        </message>
        <message>
            <source>&lt;p&gt;References: ASPRS LAS 1.4 R15, standard point classes; Kostrikov, S. et al. (2020), ISPRS IJGI 9(11), 650; IGN (2023), LiDAR HD classes.&lt;/p&gt;</source>
            <translation>&lt;p&gt;المراجع: ASPRS LAS 1.4 R15، أصناف النقاط القياسية؛ Kostrikov, S. وآخرون (2020)، ISPRS IJGI 9(11)، 650؛ IGN (2023)، أصناف LiDAR HD.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Ground</source>
            <translation>الأرض</translation>
        </message>
        <message>
            <source>Recommended ground filter</source>
            <translation>مرشح الأرض الموصى به</translation>
        </message>
        <message>
            <source>Keep the input's class 2</source>
            <translation>الإبقاء على الصنف 2 من المدخل</translation>
        </message>
        <message>
            <source>Low vegetation up to (m)</source>
            <translation>الغطاء النباتي المنخفض حتى (م)</translation>
        </message>
        <message>
            <source>Medium vegetation up to (m)</source>
            <translation>الغطاء النباتي المتوسط حتى (م)</translation>
        </message>
        <message>
            <source>Find buildings (class 6)</source>
            <translation>إيجاد المباني (الصنف 6)</translation>
        </message>
        <message>
            <source>Minimum building height above ground (m)</source>
            <translation>أدنى ارتفاع للمبنى فوق الأرض (م)</translation>
        </message>
        <message>
            <source>Keep other input classes</source>
            <translation>الإبقاء على أصناف المدخل الأخرى</translation>
        </message>
        <message>
            <source>Add height above ground</source>
            <translation>إضافة الارتفاع فوق الأرض</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>Classification report</source>
            <translation>تقرير التصنيف</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>النقاط المقروءة</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط الأرض (الصنف 2)</translation>
        </message>
        <message>
            <source>Vegetation points (classes 3-5)</source>
            <translation>نقاط الغطاء النباتي (الأصناف 3-5)</translation>
        </message>
        <message>
            <source>Building points (class 6)</source>
            <translation>نقاط المباني (الصنف 6)</translation>
        </message>
        <message>
            <source>Low noise points (class 7)</source>
            <translation>نقاط الضوضاء المنخفضة (الصنف 7)</translation>
        </message>
        <message>
            <source>Buildings</source>
            <translation>المباني</translation>
        </message>
        <message>
            <source>{} points: {} ground, {} vegetation, {} building, {} low noise; {} buildings</source>
            <translation>{} نقطة: {} أرض، {} غطاء نباتي، {} مبنى، {} ضوضاء منخفضة؛ {} مبانٍ</translation>
        </message>
    </context>
    <context>
        <name>DsmAlgorithm</name>
        <message>
            <source>DSM and nDSM / canopy height model</source>
            <translation>نموذج السطح الرقمي (DSM) والنموذج المُطبَّع (nDSM) / نموذج ارتفاع الغطاء النباتي</translation>
        </message>
        <message>
            <source>dsm,ndsm,chm,canopy height,surface model,first returns,lidar,raster</source>
            <translation>dsm,ndsm,chm,ارتفاع الغطاء النباتي,نموذج السطح,الارتدادات الأولى,ليدار,راستر</translation>
        </message>
        <message>
            <source>Excluded classes</source>
            <translation>الأصناف المستبعدة</translation>
        </message>
        <message>
            <source>First returns only</source>
            <translation>الارتدادات الأولى فقط</translation>
        </message>
        <message>
            <source>Fill empty cells up to (m)</source>
            <translation>ملء الخلايا الفارغة حتى مسافة (م)</translation>
        </message>
        <message>
            <source>DTM (for the nDSM; its grid is used)</source>
            <translation>نموذج التضاريس الرقمي DTM (لحساب nDSM؛ تُستخدم شبكته)</translation>
        </message>
        <message>
            <source>Clamp negative nDSM heights to 0</source>
            <translation>تحويل ارتفاعات nDSM السالبة إلى 0</translation>
        </message>
        <message>
            <source>DSM</source>
            <translation>نموذج السطح الرقمي (DSM)</translation>
        </message>
        <message>
            <source>nDSM / canopy height model</source>
            <translation>nDSM / نموذج ارتفاع الغطاء النباتي</translation>
        </message>
        <message>
            <source>The point cloud CRS ({}) differs from the DTM CRS ({}); give a DTM in the point cloud's CRS. No output was written.</source>
            <translation>نظام إحداثيات سحابة النقاط ({}) يختلف عن نظام إحداثيات نموذج التضاريس الرقمي ({})؛ استخدم نموذج ارتفاعات رقمياً بنظام إحداثيات سحابة النقاط. لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>The nDSM needs a DTM: give the DTM parameter (e.g. the output of the IDW DTM algorithm). No output was written.</source>
            <translation>يتطلب nDSM نموذج ارتفاعات رقمياً للأرض: حدِّد المعامل DTM (مثلاً مخرج خوارزمية نموذج التضاريس الرقمي بطريقة IDW). لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>DSM report</source>
            <translation>تقرير نموذج السطح الرقمي (DSM)</translation>
        </message>
        <message>
            <source>Builds a digital surface model from a LAS/LAZ file: each cell takes the highest return falling in it. With a DTM it also writes the normalised DSM (canopy height model in forests) = DSM − DTM on the DTM's grid.</source>
            <translation>يبني نموذج سطح رقميًا من ملف LAS/LAZ: تأخذ كل خلية أعلى انعكاس يقع فيها. ومع نموذج تضاريس رقمي يكتب أيضًا نموذج السطح المُطبَّع (نموذج ارتفاع الغطاء الشجري في الغابات) = DSM − DTM على شبكة DTM.</translation>
        </message>
        <message>
            <source>By default low and high noise.</source>
            <translation>افتراضيًا: الضجيج المنخفض والمرتفع.</translation>
        </message>
        <message>
            <source>The usual canopy surface.</source>
            <translation>سطح الغطاء الشجري المعتاد.</translation>
        </message>
        <message>
            <source>Empty cells take the nearest value within this distance; 0 = leave them nodata.</source>
            <translation>تأخذ الخلايا الفارغة أقرب قيمة ضمن هذه المسافة؛ 0 = تُترك بلا بيانات.</translation>
        </message>
        <message>
            <source>Its grid and CRS replace the cell size, extent and CRS, so that DSM and DTM align cell for cell.</source>
            <translation>تحلّ شبكته ونظام إحداثياته محلّ حجم الخلية والامتداد ونظام الإحداثيات، فيتطابق DSM وDTM خليةً بخلية.</translation>
        </message>
        <message>
            <source>Needs a DTM.</source>
            <translation>يتطلّب نموذج تضاريس رقميًا (DTM).</translation>
        </message>
        <message>
            <source>DSM cells with a value</source>
            <translation>خلايا نموذج السطح ذات القيمة</translation>
        </message>
        <message>
            <source>Maximum nDSM height</source>
            <translation>أقصى ارتفاع في نموذج السطح المُطبَّع</translation>
        </message>
    </context>
    <context>
        <name>DtmAccuracyAlgorithm</name>
        <message>
            <source>DTM accuracy against check points</source>
            <translation>دقة نموذج التضاريس الرقمي مقارنةً بنقاط التحقق</translation>
        </message>
        <message>
            <source>dtm,dem,accuracy,rmse,check points,gnss,nmad,asprs,vertical accuracy,validation</source>
            <translation>dtm,dem,الدقة,rmse,نقاط التحقق,gnss,nmad,asprs,الدقة الرأسية,التحقق من الصحة</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>نموذج التضاريس الرقمي (DTM)</translation>
        </message>
        <message>
            <source>Band</source>
            <translation>الحزمة</translation>
        </message>
        <message>
            <source>Check point file (CSV/TXT)</source>
            <translation>ملف نقاط التحقق (CSV/TXT)</translation>
        </message>
        <message>
            <source>Residuals</source>
            <translation>البواقي</translation>
        </message>
        <message>
            <source>Choose a DTM raster.</source>
            <translation>اختر طبقة راستر لنموذج التضاريس الرقمي.</translation>
        </message>
        <message>
            <source>N = {}, RMSE = {:.4f} m, ME = {:.4f} m, r = {:.5f}; {} outside, {} on nodata</source>
            <translation>⁦N = {}⁩، ⁦RMSE = {:.4f}⁩ م، ⁦ME = {:.4f}⁩ م، ⁦r = {:.5f}⁩؛ {} خارج النموذج، {} على خلايا nodata</translation>
        </message>
        <message>
            <source>Compares a DTM with independent check points (e.g. GNSS heights) and summarises the errors e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; as bias, mean absolute error, RMSE, NMAD, Pearson r and the vertical accuracy at 95 % = 1.96·RMSE (ASPRS 2014). Check points outside the DTM or on nodata are counted and excluded, never read as 0.</source>
            <translation>يقارن نموذج التضاريس الرقمي بنقاط تحقق مستقلة (مثل ارتفاعات GNSS) ويلخّص الأخطاء e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; في صورة الانحياز، ومتوسط الخطأ المطلق، وRMSE، وNMAD، ومعامل بيرسون r، والدقة الرأسية عند 95 % = 1.96·RMSE ‏(ASPRS 2014). تُحصى نقاط التحقق الواقعة خارج النموذج أو على خلايا بلا بيانات وتُستبعد، ولا تُقرأ أبدًا على أنها 0.</translation>
        </message>
        <message>
            <source>Give the layer or the file.</source>
            <translation>أدخل الطبقة أو الملف.</translation>
        </message>
        <message>
            <source>A header x/easting, y/northing, z/height (and id/name), or columns id x y z without a header.</source>
            <translation>ترويسة x/easting وy/northing وz/height (وid/name)، أو أعمدة id x y z بلا ترويسة.</translation>
        </message>
        <message>
            <source>x and y only: heights are not converted between vertical datums. Without it, check points in another CRS are an error.</source>
            <translation>x وy فقط: لا تُحوَّل الارتفاعات بين المراجع الرأسية. ومن دونه تُعدّ نقاط التحقق بنظام إحداثيات آخر خطأً.</translation>
        </message>
        <message>
            <source>Point layer with the error and status of each check point, styled by error.</source>
            <translation>طبقة نقطية فيها خطأ كل نقطة تحقق وحالتها، مُرمَّزة حسب الخطأ.</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>تقرير دقة نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Only {n} check points were compared with the DTM: ASPRS (2014) asks for at least {minimum} check points before a vertical accuracy is stated, so these statistics are indicative only. Add check points (at least {minimum}) to state an accuracy.</source>
            <translation>قورن {n} نقطة تحقق فقط بنموذج التضاريس الرقمي (DTM): تشترط ASPRS (2014) ما لا يقل عن {minimum} نقطة تحقق قبل التصريح بدقة رأسية، لذا فهذه الإحصاءات استرشادية فقط. أضف نقاط تحقق (على الأقل {minimum}) للتصريح بالدقة.</translation>
        </message>
    </context>
    <context>
        <name>ElevationChangeAlgorithm</name>
        <message>
            <source>Elevation change between two epochs (cut / fill)</source>
            <translation>تغيّر الارتفاع بين حقبتين (حفر / ردم)</translation>
        </message>
        <message>
            <source>Difference of two surveys with a 95 % level of detection, and cut and fill polygons with volumes.</source>
            <translation>فرق مسحين مع حد كشف عند 95 %، ومضلعات الحفر والردم مع أحجامها.</translation>
        </message>
        <message>
            <source>change,difference,dod,cut,fill,volume,epochs,lod,monitoring,lidar,dtm,dsm</source>
            <translation>تغيّر,فرق,dod,حفر,ردم,حجم,حقب,حد الكشف,مراقبة,ليدار,dtm,dsm</translation>
        </message>
        <message>
            <source>Before (raster or point cloud)</source>
            <translation>قبل (شبكة أو سحابة نقاط)</translation>
        </message>
        <message>
            <source>After (raster or point cloud)</source>
            <translation>بعد (شبكة أو سحابة نقاط)</translation>
        </message>
        <message>
            <source>Vertical accuracy before σ₁ (m)</source>
            <translation>الدقة الرأسية قبل σ₁ (م)</translation>
        </message>
        <message>
            <source>Vertical accuracy after σ₂ (m)</source>
            <translation>الدقة الرأسية بعد σ₂ (م)</translation>
        </message>
        <message>
            <source>Classes used (clouds)</source>
            <translation>الأصناف المستخدمة (للسحب)</translation>
        </message>
        <message>
            <source>Cell size (m, clouds)</source>
            <translation>حجم الخلية (م، للسحب)</translation>
        </message>
        <message>
            <source>Minimum region area (m², 0 = 8 cells)</source>
            <translation>أدنى مساحة للمنطقة (م²، 0 = 8 خلايا)</translation>
        </message>
        <message>
            <source>Difference</source>
            <translation>الفرق</translation>
        </message>
        <message>
            <source>Change polygons</source>
            <translation>مضلعات التغيّر</translation>
        </message>
        <message>
            <source>Subtracts an earlier surface from a later one (two rasters on one grid, or two LAS/LAZ clouds gridded by TIN) and keeps the change beyond the level of detection LoD95 = 1.96·√(σ₁² + σ₂²). Significant cells form cut and fill polygons with area, mean change and volume.</source>
            <translation>يطرح سطحًا سابقًا من سطح لاحق (نموذجان نقطيان على شبكة واحدة، أو سحابتا LAS/LAZ محوّلتان إلى شبكة بطريقة TIN) ويحتفظ بالتغيّر الذي يتجاوز حدّ الكشف LoD95 = 1.96·√(σ₁² + σ₂²). تُشكّل الخلايا المعنوية مضلعات حفر وردم بمساحتها ومتوسط تغيّرها وحجمها.</translation>
        </message>
        <message>
            <source>A GeoTIFF, or a LAS/LAZ cloud in the same CRS as the other epoch.</source>
            <translation>ملف GeoTIFF، أو سحابة LAS/LAZ بنظام إحداثيات الحقبة الأخرى نفسه.</translation>
        </message>
        <message>
            <source>The vertical accuracy of the epoch, e.g. the RMSE of the DTM accuracy tool.</source>
            <translation>الدقة الرأسية للحقبة، مثل RMSE من أداة دقة نموذج التضاريس.</translation>
        </message>
        <message>
            <source>Smaller regions are dropped: noise alone exceeds the LoD in 5 % of cells.</source>
            <translation>تُحذف المناطق الأصغر: فالضجيج وحده يتجاوز حدّ الكشف في 5 % من الخلايا.</translation>
        </message>
        <message>
            <source>GeoTIFF of after − before (m).</source>
            <translation>ملف GeoTIFF للفرق اللاحق − السابق (m).</translation>
        </message>
        <message>
            <source>GeoPackage with kind (cut / fill), area, mean change and volume.</source>
            <translation>ملف GeoPackage بالنوع (حفر / ردم) والمساحة ومتوسط التغيّر والحجم.</translation>
        </message>
        <message>
            <source>Elevation change report</source>
            <translation>تقرير تغيّر الارتفاع</translation>
        </message>
        <message>
            <source>The residual layer of a DTM accuracy run on this epoch: σ becomes the RMSE of its residuals (status used) and the typed σ is ignored.</source>
            <translation>طبقة البواقي الناتجة عن تشغيل أداة دقة نموذج التضاريس الرقمي على هذه الحقبة: تصبح σ جذر متوسط مربعات بواقيها (الحالة used) وتُتجاهل قيمة σ المكتوبة.</translation>
        </message>
        <message>
            <source>A raster on another grid in the same CRS is resampled (bilinear) onto the first one's grid.</source>
            <translation>تُعاد معاينة النقطية ذات الشبكة المختلفة في نظام الإحداثيات نفسه (ثنائي خطي) على شبكة النقطية الأولى.</translation>
        </message>
        <message>
            <source>σ₁ from a DTM accuracy run (residual layer, optional)</source>
            <translation>σ₁ من تشغيل أداة دقة نموذج التضاريس الرقمي (طبقة البواقي، اختياري)</translation>
        </message>
        <message>
            <source>σ₂ from a DTM accuracy run (residual layer, optional)</source>
            <translation>σ₂ من تشغيل أداة دقة نموذج التضاريس الرقمي (طبقة البواقي، اختياري)</translation>
        </message>
        <message>
            <source>The second raster ({0} × {1} cells of {2:g} m) is resampled (bilinear) onto the first one's grid ({3} × {4} cells of {5:g} m).</source>
            <translation>تُعاد معاينة النقطية الثانية ({0} × {1} خلية بحجم {2:g} م) بطريقة ثنائية خطية على شبكة النقطية الأولى ({3} × {4} خلية بحجم {5:g} م).</translation>
        </message>
        <message>
            <source>{0} = {1:.4f} m: RMSE of {2} check-point residuals of {3}</source>
            <translation>{0} = {1:.4f} م: جذر متوسط مربعات {2} من بواقي نقاط التحقق في {3}</translation>
        </message>
        <message>
            <source>A raster layer of the project or a raster file; give each epoch once, as a file or as a raster layer.</source>
            <translation>طبقة نقطية من المشروع أو ملف نقطي؛ أعطِ كل حقبة مرة واحدة، كملف أو كطبقة نقطية.</translation>
        </message>
        <message>
            <source>Before as a raster layer (instead of a file)</source>
            <translation>قبل، كطبقة نقطية (بدلًا من ملف)</translation>
        </message>
        <message>
            <source>After as a raster layer (instead of a file)</source>
            <translation>بعد، كطبقة نقطية (بدلًا من ملف)</translation>
        </message>
        <message>
            <source>Level of detection LoD95 (m)</source>
            <translation>حد الكشف LoD95 (م)</translation>
        </message>
        <message>
            <source>Fill volume above the LoD (m³)</source>
            <translation>حجم الردم فوق حد الكشف (م³)</translation>
        </message>
        <message>
            <source>Cut volume above the LoD (m³)</source>
            <translation>حجم الحفر فوق حد الكشف (م³)</translation>
        </message>
        <message>
            <source>Change regions</source>
            <translation>مناطق التغيّر</translation>
        </message>
        <message>
            <source>{0} has no CRS: it is taken to be in the CRS of {1} ({2}); check that it is.</source>
            <translation>{0} بلا نظام إحداثيات: يُعدّ في نظام إحداثيات {1} ({2})؛ تحقّق من ذلك.</translation>
        </message>
    </context>
    <context>
        <name>GcpAccuracyReportAlgorithm</name>
        <message>
            <source>GCP accuracy report</source>
            <translation>تقرير دقة نقاط الضبط الأرضي</translation>
        </message>
        <message>
            <source>georeference,gcp,ground control points,rms,residuals,accuracy,check points,leave-one-out,polynomial,georeferencer</source>
            <translation>إسناد جغرافي,gcp,نقاط الضبط الأرضي,rms,البواقي,الدقة,نقاط التحقق,الاستبعاد الفردي,متعدد الحدود,georeferencer</translation>
        </message>
        <message>
            <source>Image width (px) if no image is given</source>
            <translation>عرض الصورة (بكسل) إن لم تُحدَّد صورة</translation>
        </message>
        <message>
            <source>Image height (px) if no image is given</source>
            <translation>ارتفاع الصورة (بكسل) إن لم تُحدَّد صورة</translation>
        </message>
        <message>
            <source>Residuals table</source>
            <translation>جدول البواقي</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>ملفات CSV (*.csv)</translation>
        </message>
        <message>
            <source>JSON files (*.json)</source>
            <translation>ملفات JSON (*.json)</translation>
        </message>
        <message>
            <source>Judges a set of ground control points without warping: every transformation side by side by the paper's criteria on check points and leave-one-out residuals. It recommends one transformation, says why, and suggests points to drop.</source>
            <translation>يقيّم مجموعة نقاط ضبط أرضي دون تطويع الصورة: كل التحويلات جنبًا إلى جنب وفق معايير الورقة على نقاط التحقق وبواقي الاستبعاد الفردي. ويوصي بتحويل واحد ويبيّن السبب ويقترح نقاطًا للحذف.</translation>
        </message>
        <message>
            <source>Gives the image size; without it give the image width and height, or the GCP centroid is used.</source>
            <translation>تعطي حجم الصورة؛ ومن دونها أدخل عرض الصورة وارتفاعها، وإلا استُخدم مركز نقاط الضبط.</translation>
        </message>
        <message>
            <source>One row per point with its residuals in map units and pixels.</source>
            <translation>صف لكل نقطة ببواقيها بوحدات الخريطة وبالبكسل.</translation>
        </message>
        <message>
            <source>GCP accuracy report as JSON</source>
            <translation>تقرير دقة نقاط الضبط الأرضي بصيغة JSON</translation>
        </message>
        <message>
            <source>RMS_T of order {} (map units)</source>
            <translation>RMS_T للرتبة {} (وحدات الخريطة)</translation>
        </message>
        <message>
            <source>Leave-one-out RMS_T of order {}</source>
            <translation>RMS_T بطريقة ترك واحدة للرتبة {}</translation>
        </message>
        <message>
            <source>Order {order}: RMS_T = {rms:.4f} {unit} (divisor n), {qgis} {unit} (divisor n − N); {within}/{n} within RMS_T; verdict: {verdict}.</source>
            <translation>الرتبة {order}: ⁦RMS_T = {rms:.4f} {unit}⁩ (المقسوم عليه n)، {qgis} {unit} (المقسوم عليه n − N)؛ {within}/{n} ضمن RMS_T؛ الحكم: {verdict}.</translation>
        </message>
        <message>
            <source>Recommended polynomial order: {order}.</source>
            <translation>رتبة كثيرة الحدود الموصى بها: {order}.</translation>
        </message>
        <message>
            <source>No polynomial order has enough redundancy to be recommended (n ≥ 5, 9, 15 GCPs for orders 1, 2, 3).</source>
            <translation>لا توجد رتبة كثيرة حدود ذات فائض كافٍ للتوصية بها (n ≥ 5 و9 و15 نقطة ضبط للرتب 1 و2 و3).</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsAlgorithm</name>
        <message>
            <source>LiDAR ground filtering</source>
            <translation>ترشيح نقاط الأرض في بيانات الليدار</translation>
        </message>
        <message>
            <source>Terrain models</source>
            <translation>نماذج التضاريس</translation>
        </message>
        <message>
            <source>Image rectification</source>
            <translation>التصحيح الهندسي للصور</translation>
        </message>
        <message>
            <source>Photogrammetry</source>
            <translation>المساحة التصويرية</translation>
        </message>
        <message>
            <source>Accuracy assessment</source>
            <translation>تقييم الدقة</translation>
        </message>
        <message>
            <source>Cancelled by the user; no output was written.</source>
            <translation>ألغى المستخدم العملية؛ لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>Out of memory. Use a coarser cell size, a smaller extent or fewer points; no output was written.</source>
            <translation>نفدت الذاكرة. استخدم حجم خلية أكبر أو نطاقاً أصغر أو نقاطاً أقل؛ لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>Remove low outliers first (class 7)</source>
            <translation>إزالة القيم الشاذة المنخفضة أولاً (الصنف 7)</translation>
        </message>
        <message>
            <source>Low-outlier search cell (m)</source>
            <translation>خلية البحث عن القيم الشاذة المنخفضة (م)</translation>
        </message>
        <message>
            <source>Low-outlier depth below neighbours (m)</source>
            <translation>عمق القيمة الشاذة المنخفضة تحت الجيران (م)</translation>
        </message>
        <message>
            <source>Report language</source>
            <translation>لغة التقرير</translation>
        </message>
        <message>
            <source>Interface language</source>
            <translation>لغة الواجهة</translation>
        </message>
        <message>
            <source>Terminated; no output was written.</source>
            <translation>أُنهي التشغيل؛ لم يُكتب أي ناتج.</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>The point-cloud layer '{name}' is not a local .las/.laz file ({source}): export it to LAS/LAZ first.</source>
            <translation>طبقة سحابة النقاط '{name}' ليست ملف ‎.las/.laz‏ محليًا ({source}): صدّرها إلى LAS/LAZ أولًا.</translation>
        </message>
        <message>
            <source>Created, never classified</source>
            <translation>مُنشأة، لم تُصنَّف قط</translation>
        </message>
        <message>
            <source>Unclassified</source>
            <translation>غير مصنّفة</translation>
        </message>
        <message>
            <source>Ground</source>
            <translation>الأرض</translation>
        </message>
        <message>
            <source>Low vegetation</source>
            <translation>نباتات منخفضة</translation>
        </message>
        <message>
            <source>Medium vegetation</source>
            <translation>نباتات متوسطة</translation>
        </message>
        <message>
            <source>High vegetation</source>
            <translation>نباتات عالية</translation>
        </message>
        <message>
            <source>Building</source>
            <translation>مبنى</translation>
        </message>
        <message>
            <source>Low point (noise)</source>
            <translation>نقطة منخفضة (ضجيج)</translation>
        </message>
        <message>
            <source>Reserved (model key-point)</source>
            <translation>محجوزة (نقطة مفتاحية للنموذج)</translation>
        </message>
        <message>
            <source>Water</source>
            <translation>ماء</translation>
        </message>
        <message>
            <source>Rail</source>
            <translation>سكة حديد</translation>
        </message>
        <message>
            <source>Road surface</source>
            <translation>سطح طريق</translation>
        </message>
        <message>
            <source>Reserved (overlap)</source>
            <translation>محجوزة (تداخل)</translation>
        </message>
        <message>
            <source>Wire – guard (shield)</source>
            <translation>سلك – حماية (واقٍ)</translation>
        </message>
        <message>
            <source>Wire – conductor (phase)</source>
            <translation>سلك – موصل (طور)</translation>
        </message>
        <message>
            <source>Transmission tower</source>
            <translation>برج نقل كهرباء</translation>
        </message>
        <message>
            <source>Wire-structure connector (insulator)</source>
            <translation>وصلة سلك بهيكل (عازل)</translation>
        </message>
        <message>
            <source>Bridge deck</source>
            <translation>سطح جسر</translation>
        </message>
        <message>
            <source>High noise</source>
            <translation>ضجيج مرتفع</translation>
        </message>
        <message>
            <source>Overhead structure</source>
            <translation>منشأة علوية</translation>
        </message>
        <message>
            <source>Ignored ground</source>
            <translation>أرض مُتجاهَلة</translation>
        </message>
        <message>
            <source>Snow</source>
            <translation>ثلج</translation>
        </message>
        <message>
            <source>Temporal exclusion</source>
            <translation>استبعاد زمني</translation>
        </message>
        <message>
            <source>Example</source>
            <translation>مثال</translation>
        </message>
        <message>
            <source>Parameters</source>
            <translation>المعاملات</translation>
        </message>
        <message>
            <source>Also returned</source>
            <translation>تُعاد أيضًا</translation>
        </message>
        <message>
            <source>default: {}</source>
            <translation>الافتراضي: {}</translation>
        </message>
        <message>
            <source>optional</source>
            <translation>اختياري</translation>
        </message>
        <message>
            <source>advanced</source>
            <translation>متقدّم</translation>
        </message>
        <message>
            <source>yes</source>
            <translation>نعم</translation>
        </message>
        <message>
            <source>no</source>
            <translation>لا</translation>
        </message>
        <message>
            <source>Check points used</source>
            <translation>نقاط التحقق المستخدمة</translation>
        </message>
        <message>
            <source>Check points outside the DTM</source>
            <translation>نقاط التحقق خارج نموذج التضاريس</translation>
        </message>
        <message>
            <source>Check points on DTM nodata</source>
            <translation>نقاط التحقق على خلايا بلا بيانات في نموذج التضاريس</translation>
        </message>
        <message>
            <source>Mean error (m)</source>
            <translation>متوسط الخطأ (م)</translation>
        </message>
        <message>
            <source>Mean absolute error (m)</source>
            <translation>متوسط الخطأ المطلق (م)</translation>
        </message>
        <message>
            <source>RMSE (m)</source>
            <translation>جذر متوسط مربع الخطأ RMSE (م)</translation>
        </message>
        <message>
            <source>Standard deviation of the errors (m)</source>
            <translation>الانحراف المعياري للأخطاء (م)</translation>
        </message>
        <message>
            <source>Maximum absolute error (m)</source>
            <translation>أقصى خطأ مطلق (م)</translation>
        </message>
        <message>
            <source>Pearson r</source>
            <translation>معامل ارتباط بيرسون r</translation>
        </message>
        <message>
            <source>R²</source>
            <translation>معامل التحديد R²</translation>
        </message>
        <message>
            <source>NMAD (m)</source>
            <translation>الانحراف المطلق الوسيط المُطبَّع NMAD (م)</translation>
        </message>
        <message>
            <source>Vertical accuracy at 95 % = 1.96·RMSE (m)</source>
            <translation>الدقة الرأسية عند 95 % = 1.96·RMSE (م)</translation>
        </message>
        <message>
            <source>reference ground → filtered ground</source>
            <translation>أرض في المرجع ← أرض بعد الترشيح</translation>
        </message>
        <message>
            <source>reference ground → filtered object (Type I)</source>
            <translation>أرض في المرجع ← جسم بعد الترشيح (النوع الأول)</translation>
        </message>
        <message>
            <source>reference object → filtered ground (Type II)</source>
            <translation>جسم في المرجع ← أرض بعد الترشيح (النوع الثاني)</translation>
        </message>
        <message>
            <source>reference object → filtered object</source>
            <translation>جسم في المرجع ← جسم بعد الترشيح</translation>
        </message>
        <message>
            <source>points</source>
            <translation>عدد النقاط</translation>
        </message>
        <message>
            <source>Type I error (%)</source>
            <translation>خطأ النوع الأول (٪)</translation>
        </message>
        <message>
            <source>Type II error (%)</source>
            <translation>خطأ النوع الثاني (٪)</translation>
        </message>
        <message>
            <source>Total error (%)</source>
            <translation>الخطأ الإجمالي (٪)</translation>
        </message>
        <message>
            <source>Cohen's kappa (%)</source>
            <translation>معامل كابا لكوهين (%)</translation>
        </message>
        <message>
            <source>Nearest neighbour (near)</source>
            <translation>أقرب جار (near)</translation>
        </message>
        <message>
            <source>Cubic convolution (cubic)</source>
            <translation>الالتفاف التكعيبي (cubic)</translation>
        </message>
        <message>
            <source>Cubic spline (cubicspline)</source>
            <translation>الشريحة التكعيبية (cubicspline)</translation>
        </message>
        <message>
            <source>Lanczos windowed sinc (lanczos)</source>
            <translation>دالة sinc المُنوفذة لـ Lanczos (lanczos)</translation>
        </message>
        <message>
            <source>Most frequent value (mode)</source>
            <translation>القيمة الأكثر تكرارًا (mode)</translation>
        </message>
        <message>
            <source>RMS_x (map units, divisor n)</source>
            <translation>RMS_x (وحدات الخريطة، المقسوم عليه n)</translation>
        </message>
        <message>
            <source>RMS_y (map units, divisor n)</source>
            <translation>RMS_y (وحدات الخريطة، المقسوم عليه n)</translation>
        </message>
        <message>
            <source>RMS_T (map units, divisor n)</source>
            <translation>RMS_T (وحدات الخريطة، المقسوم عليه n)</translation>
        </message>
        <message>
            <source>RMS_T with divisor n − N (QGIS Georeferencer)</source>
            <translation>RMS_T بالمقسوم عليه n − N (مُرجِع QGIS الجغرافي)</translation>
        </message>
        <message>
            <source>Ground resolution GR (map units/pixel)</source>
            <translation>الدقة الأرضية GR (وحدات الخريطة/بكسل)</translation>
        </message>
        <message>
            <source>Map scale number S = 20000·GR</source>
            <translation>رقم مقياس الخريطة S = 20000·GR</translation>
        </message>
        <message>
            <source>GCPs used in the fit</source>
            <translation>نقاط الضبط المستخدمة في المواءمة</translation>
        </message>
        <message>
            <source>Redundancy n − N</source>
            <translation>درجة الفائض n − N</translation>
        </message>
        <message>
            <source>Points with RMS_i ≤ RMS_T</source>
            <translation>النقاط ذات RMS_i ≤ RMS_T</translation>
        </message>
        <message>
            <source>Leave-one-out RMS_T (map units)</source>
            <translation>RMS_T بطريقة ترك واحدة (وحدات الخريطة)</translation>
        </message>
        <message>
            <source>Check-point RMS_T (map units)</source>
            <translation>RMS_T لنقاط التحقق (وحدات الخريطة)</translation>
        </message>
        <message>
            <source>Independent check points</source>
            <translation>نقاط التحقق المستقلة</translation>
        </message>
        <message>
            <source>Recommended order (0 = none)</source>
            <translation>الرتبة المُوصى بها (0 = لا شيء)</translation>
        </message>
        <message>
            <source>Accepted by criteria C4–C6 (1/0)</source>
            <translation>مقبول وفق المعايير C4–C6 (1/0)</translation>
        </message>
        <message>
            <source>GCPs dropped by the refinement</source>
            <translation>النقاط المحذوفة بالتنقيح</translation>
        </message>
        <message>
            <source>Check-point (else leave-one-out) RMS_T of the transformation used</source>
            <translation>RMS_T لنقاط التحقق (وإلا فبطريقة ترك واحدة) للتحويل المستخدم</translation>
        </message>
        <message>
            <source>Colour ramp</source>
            <translation>تدرّج لوني</translation>
        </message>
        <message>
            <source>Hillshade</source>
            <translation>تظليل التضاريس</translation>
        </message>
        <message>
            <source>Cut (surface lowered)</source>
            <translation>حفر (انخفض السطح)</translation>
        </message>
        <message>
            <source>Fill (surface raised)</source>
            <translation>ردم (ارتفع السطح)</translation>
        </message>
        <message>
            <source>Could not style the layer {name}: {error}</source>
            <translation>تعذّر تطبيق النمط على الطبقة {name}: {error}</translation>
        </message>
        <message>
            <source>Linear</source>
            <translation>خطي (linear)</translation>
        </message>
        <message>
            <source>Power</source>
            <translation>أُسّية القوة (power)</translation>
        </message>
        <message>
            <source>Gaussian</source>
            <translation>غاوسي (gaussian)</translation>
        </message>
        <message>
            <source>Spherical</source>
            <translation>كروي (spherical)</translation>
        </message>
        <message>
            <source>Exponential</source>
            <translation>أُسّي (exponential)</translation>
        </message>
        <message>
            <source>Bilinear</source>
            <translation>ثنائي الخطية</translation>
        </message>
        <message>
            <source>Average</source>
            <translation>المتوسط (average)</translation>
        </message>
        <message>
            <source>The data are in {} horizontally and {} vertically; they are converted to metres, so every length you give and every length in this log is in metres.</source>
            <translation>البيانات بوحدة {} أفقياً و{} رأسياً؛ تُحوَّل إلى الأمتار، لذا فكل طول تُدخله وكل طول في هذا السجل بالأمتار.</translation>
        </message>
        <message>
            <source>Project name (shown in the report)</source>
            <translation>اسم المشروع (يظهر في التقرير)</translation>
        </message>
        <message>
            <source>Operator (shown in the report)</source>
            <translation>المشغّل (يظهر في التقرير)</translation>
        </message>
        <message>
            <source>Set-up</source>
            <translation>الإعداد</translation>
        </message>
        <message>
            <source>Pick a loaded point-cloud layer or a .las, .laz or .copc.laz file.</source>
            <translation>اختر طبقة سحابة نقاط محمّلة أو ملف ‎.las‏ أو ‎.laz‏ أو ‎.copc.laz‏.</translation>
        </message>
        <message>
            <source>This QGIS build has no PDAL point-cloud provider: .las/.laz files cannot be loaded as layers here, COPC files (.copc.laz) can (QGIS 3.26 and later read them without PDAL). Give the .las, .laz or .copc.laz file.</source>
            <translation>نسخة QGIS هذه لا تحتوي على مزوّد سحب النقاط PDAL: لا يمكن تحميل ملفات ‎.las/.laz‏ كطبقات هنا، أما ملفات COPC ‏(‎.copc.laz‏) فيمكن تحميلها (يقرؤها QGIS 3.26 وما بعده دون PDAL). أعطِ ملف ‎.las‏ أو ‎.laz‏ أو ‎.copc.laz‏.</translation>
        </message>
        <message>
            <source>This QGIS build has no PDAL point-cloud provider, so point clouds cannot be loaded as layers (COPC needs QGIS 3.26 or later): give the .las, .laz or .copc.laz file.</source>
            <translation>نسخة QGIS هذه لا تحتوي على مزوّد سحب النقاط PDAL، لذا لا يمكن تحميل سحب النقاط كطبقات (يتطلب COPC الإصدار QGIS 3.26 أو أحدث): أعطِ ملف ‎.las‏ أو ‎.laz‏ أو ‎.copc.laz‏.</translation>
        </message>
        <message>
            <source>Its default was chosen by leave-one-sample-out cross-validation over the ISPRS samples and synthetic forest, cliff, lake and bridge scenes (benchmarks/results/defaults.md).</source>
            <translation>اختير افتراضيه بالتحقق المتقاطع بترك عيّنة واحدة خارجاً على عيّنات ISPRS ومشاهد اصطناعية لغابة وجروف وبحيرة وجسر (benchmarks/results/defaults.md).</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsProvider</name>
        <message>
            <source>Geomatics Toolbox</source>
            <translation>صندوق أدوات الجيوماتكس</translation>
        </message>
        <message>
            <source>LiDAR to DTM with accuracy</source>
            <translation>من LiDAR إلى نموذج تضاريس رقمي مع الدقة</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>حجم خلية نموذج التضاريس (م)</translation>
        </message>
        <message>
            <source>IDW power</source>
            <translation>أس IDW</translation>
        </message>
        <message>
            <source>Fill data gaps in the DTM (interpolate far from ground points)</source>
            <translation>ملء فجوات البيانات في نموذج التضاريس (الاستكمال بعيدًا عن نقاط الأرض)</translation>
        </message>
        <message>
            <source>CRS override for a cloud without a CRS record</source>
            <translation>نظام إحداثيات بديل لسحابة بلا سجل نظام إحداثيات</translation>
        </message>
        <message>
            <source>Check points (point layer)</source>
            <translation>نقاط التحقق (طبقة نقطية)</translation>
        </message>
        <message>
            <source>Check points (CSV/TXT file: id,x,y,z)</source>
            <translation>نقاط التحقق (ملف CSV/TXT: ‏id,x,y,z)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>تقرير مرشح الأرض</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>نموذج التضاريس الرقمي (DTM)</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>تقرير نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>بواقي نقاط التحقق</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>تقرير دقة نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>The editable model of 'LiDAR to DTM with accuracy': the same steps, defaults and results; open it in the Model Designer to change a step.</source>
            <translation>النموذج القابل للتحرير من 'من LiDAR إلى نموذج تضاريس رقمي مع الدقة': الخطوات نفسها والقيم الافتراضية نفسها والنتائج نفسها؛ افتحه في مصمم النماذج لتغيير خطوة.</translation>
        </message>
        <message>
            <source>&lt;p&gt;Ground filter (recommended) → DTM by IDW → DTM accuracy against check points, as a Processing model you can open and change in the Model Designer. With its defaults it gives the same classified cloud, DTM and RMSE, bit for bit, as the one-step algorithm 'LiDAR to DTM with accuracy' and as the three algorithms run one after another. Its steps write temporary files and a last step publishes them all or none: when a step fails, nothing is left at any destination.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;: the point cloud (LAS/LAZ, projected CRS), the DTM cell size (m, default 1), the IDW power (default 2), fill data gaps (default no), a CRS for a cloud without one, and the check points (a point layer or a CSV/TXT file id,x,y,z).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Outputs&lt;/b&gt;: classified point cloud, DTM, DTM accuracy report; optionally the ground filter report, the DTM report and the check-point residuals.&lt;/p&gt;</source>
            <translation>&lt;p&gt;مرشح الأرض (الموصى به) ← نموذج التضاريس الرقمي بطريقة IDW ← دقة نموذج التضاريس الرقمي مقابل نقاط التحقق، في نموذج معالجة يمكنك فتحه وتغييره في مصمم النماذج. بقيمه الافتراضية يعطي سحابة النقاط المصنفة ونموذج التضاريس الرقمي وRMSE نفسها، بتاً ببت، التي تعطيها الخوارزمية ذات الخطوة الواحدة 'من LiDAR إلى نموذج تضاريس رقمي مع الدقة' والخوارزميات الثلاث مشغّلة الواحدة تلو الأخرى. تكتب خطواته ملفات مؤقتة وتنشرها خطوة أخيرة كلها أو لا شيء: إذا فشلت خطوة لا يبقى شيء في أي وجهة.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;: سحابة النقاط (LAS/LAZ، نظام إحداثيات مسقط)، وحجم خلية نموذج التضاريس (م، الافتراضي 1)، وأس IDW (الافتراضي 2)، وملء فجوات البيانات (الافتراضي لا)، ونظام إحداثيات لسحابة بلا نظام، ونقاط التحقق (طبقة نقطية أو ملف CSV/TXT ‏id,x,y,z).&lt;/p&gt;&lt;p&gt;&lt;b&gt;المخرجات&lt;/b&gt;: سحابة النقاط المصنفة، ونموذج التضاريس الرقمي، وتقرير دقة نموذج التضاريس الرقمي؛ واختيارياً تقرير مرشح الأرض وتقرير نموذج التضاريس الرقمي وبواقي نقاط التحقق.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Project name (shown in the report)</source>
            <translation>اسم المشروع (يظهر في التقرير)</translation>
        </message>
        <message>
            <source>Operator (shown in the report)</source>
            <translation>المشغّل (يظهر في التقرير)</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsToolboxPlugin</name>
        <message>
            <source>{packages} for the LiDAR algorithms</source>
            <translation>{packages} لخوارزميات ليدار</translation>
        </message>
        <message>
            <source>{packages} for the tile catalog</source>
            <translation>{packages} لفهرس البلاطات</translation>
        </message>
        <message>
            <source>QGIS's Python lacks Python packages this toolbox needs: {missing}. The other algorithms work without them.</source>
            <translation>تنقص Python الخاص بـ QGIS حزمُ Python يحتاجها صندوق الأدوات هذا: {missing}. تعمل الخوارزميات الأخرى من دونها.</translation>
        </message>
        <message>
            <source>Geomatics Toolbox</source>
            <translation>صندوق أدوات الجيوماتكس</translation>
        </message>
        <message>
            <source>Install them…</source>
            <translation>ثبّتها…</translation>
        </message>
        <message>
            <source>{packages} for every algorithm</source>
            <translation>{packages} لكل الخوارزميات</translation>
        </message>
        <message>
            <source>QGIS's Python lacks Python packages this toolbox needs: {missing}. Until they are installed only the installer is offered.</source>
            <translation>تنقص Python الخاص بـ QGIS حزمُ Python يحتاجها صندوق الأدوات هذا: {missing}. إلى أن تُثبَّت لا يُعرض إلا المثبّت.</translation>
        </message>
    </context>
    <context>
        <name>GroundFilterAccuracyAlgorithm</name>
        <message>
            <source>Ground filter accuracy</source>
            <translation>دقة مرشح نقاط الأرض</translation>
        </message>
        <message>
            <source>lidar,ground,filter,accuracy,type i,type ii,total error,kappa,isprs,reference,confusion matrix</source>
            <translation>ليدار,أرض,مرشح,الدقة,النوع الأول,النوع الثاني,الخطأ الكلي,كابا,isprs,مرجع,مصفوفة الالتباس</translation>
        </message>
        <message>
            <source>Filtered point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط المرشحة (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Class dimension of the filtered cloud</source>
            <translation>بُعد الصنف في السحابة المرشحة</translation>
        </message>
        <message>
            <source>Ground classes of the filtered cloud</source>
            <translation>أصناف الأرض في السحابة المرشحة</translation>
        </message>
        <message>
            <source>Reference point cloud (same points, same order)</source>
            <translation>سحابة النقاط المرجعية (النقاط نفسها وبالترتيب نفسه)</translation>
        </message>
        <message>
            <source>Reference class dimension</source>
            <translation>بُعد الصنف في المرجع</translation>
        </message>
        <message>
            <source>Reference ground classes</source>
            <translation>أصناف الأرض في المرجع</translation>
        </message>
        <message>
            <source>Per-point error layer (user_data: 0 correct, 1 Type I, 2 Type II)</source>
            <translation>طبقة الخطأ لكل نقطة (user_data: 0 صحيح، 1 النوع الأول، 2 النوع الثاني)</translation>
        </message>
        <message>
            <source>Compares a filtered point cloud with reference labels using the measures of the ISPRS filter test (Sithole &amp;amp; Vosselman 2004): the cross matrix, Type I = b/(a+b), Type II = c/(c+d), total error and Cohen's kappa. An optional per-point error cloud shows where the filter fails.</source>
            <translation>يقارن سحابة نقاط مرشَّحة بتصنيفات مرجعية وفق مقاييس اختبار المرشحات لـ ISPRS ‏(Sithole &amp;amp; Vosselman 2004): المصفوفة المتقاطعة، والنوع الأول = b/(a+b)، والنوع الثاني = c/(c+d)، والخطأ الكلي، ومعامل كابا لكوهين. وتُظهر سحابة أخطاء اختيارية لكل نقطة أين يخفق المرشح.</translation>
        </message>
        <message>
            <source>A list such as 2,8 is accepted; every other class counts as an object.</source>
            <translation>تُقبل قائمة مثل 2,8؛ وتُعدّ كل فئة أخرى جسمًا.</translation>
        </message>
        <message>
            <source>Checked: equal count and coordinates. When empty, the reference labels are read from another dimension of the filtered cloud.</source>
            <translation>يُتحقَّق من تساوي العدد والإحداثيات. وإن تُرك فارغًا تُقرأ التصنيفات المرجعية من بُعد آخر في السحابة المرشَّحة.</translation>
        </message>
        <message>
            <source>E.g. user_data or an extra dimension when there is no reference cloud.</source>
            <translation>مثل user_data أو بُعد إضافي عند غياب سحابة مرجعية.</translation>
        </message>
        <message>
            <source>A copy of the filtered cloud; style it by user_data to map the errors.</source>
            <translation>نسخة من السحابة المرشَّحة؛ رمّزها حسب user_data لترى الأخطاء على الخريطة.</translation>
        </message>
        <message>
            <source>Ground filter accuracy report</source>
            <translation>تقرير دقة مرشح الأرض</translation>
        </message>
    </context>
    <context>
        <name>GroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (recommended)</source>
            <translation>مرشح الأرض (الموصى به)</translation>
        </message>
        <message>
            <source>Classifies ground in a LAS/LAZ cloud with no parameter to set.</source>
            <translation>يصنّف الأرض في سحابة LAS/LAZ دون أي معامل يجب ضبطه.</translation>
        </message>
        <message>
            <source>&lt;p&gt;References: Pingel, T. J., Clarke, K. C. &amp;amp; McBride, W. A. (2013), ISPRS J. Photogramm. Remote Sens. 77, 21–30; Zhang, K. et al. (2003), IEEE TGRS 41(4), 872–882.&lt;/p&gt;</source>
            <translation>&lt;p&gt;المراجع: Pingel, T. J., Clarke, K. C. &amp;amp; McBride, W. A. (2013), ISPRS J. Photogramm. Remote Sens. 77, 21–30؛ Zhang, K. et al. (2003), IEEE TGRS 41(4), 872–882.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Raster cell, 0 = derived (m)</source>
            <translation>خلية الشبكة النقطية، 0 = مشتقة (م)</translation>
        </message>
        <message>
            <source>Largest window, &gt; largest building (m)</source>
            <translation>أكبر نافذة، &gt; أكبر مبنى (م)</translation>
        </message>
        <message>
            <source>Slope tolerance, 0 = derived (rise/run)</source>
            <translation>سماحية الانحدار، 0 = مشتقة (ارتفاع/مسافة)</translation>
        </message>
        <message>
            <source>Refinement passes</source>
            <translation>تمريرات التحسين</translation>
        </message>
        <message>
            <source>Remove low outliers first (class 7)</source>
            <translation>إزالة القيم الشاذة المنخفضة أولاً (الصنف 7)</translation>
        </message>
        <message>
            <source>Low-outlier search cell (m)</source>
            <translation>خلية البحث عن القيم الشاذة المنخفضة (م)</translation>
        </message>
        <message>
            <source>Low-outlier depth below neighbours (m)</source>
            <translation>عمق القيمة الشاذة المنخفضة تحت الجيران (م)</translation>
        </message>
        <message>
            <source>0 = derived from the point density (about 1 m).</source>
            <translation>0 = مشتق من كثافة النقاط (نحو 1 م).</translation>
        </message>
        <message>
            <source>Must exceed the largest building.</source>
            <translation>يجب أن يتجاوز أكبر مبنى.</translation>
        </message>
        <message>
            <source>0 = half the local terrain slope (0.10 to 0.60).</source>
            <translation>0 = نصف انحدار التضاريس المحلي (من 0.10 إلى 0.60).</translation>
        </message>
        <message>
            <source>Passes that rebuild the terrain from the accepted points.</source>
            <translation>تمريرات تعيد بناء التضاريس من النقاط المقبولة.</translation>
        </message>
        <message>
            <source>Height tolerance, 0 = derived (m)</source>
            <translation>سماحية الارتفاع، 0 = مشتقة (م)</translation>
        </message>
        <message>
            <source>Recommended ground filter: window {} m, {} refinement passes; cell and tolerances derived from the cloud (see the report)</source>
            <translation>مرشح الأرض الموصى به: النافذة {} م، {} تمريرات تحسين؛ الخلية والسماحيات مشتقة من السحابة (انظر التقرير)</translation>
        </message>
        <message>
            <source>0 = 0.35 × the mean point spacing, 0.25 to 0.5 m; plus 1.0 m per unit of terrain slope.</source>
            <translation>0 = ‏0.35 × متوسط تباعد النقاط، من 0.25 إلى 0.5 م؛ زائد 1.0 م لكل وحدة من انحدار التضاريس.</translation>
        </message>
        <message>
            <source>Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) with no parameter to set: a progressive morphological filter (Pingel et al. 2013) whose cell, slope and height tolerances are derived from the cloud, applied to the terrain with its regional slope removed; terrain crests it removed are grown back, then passes rebuild the terrain and re-test every point. Under a closed canopy lone ground returns are kept, so the terrain never climbs into the trees; water classified 9 in the input keeps its class, and flat, sparse patches that look like water get class 1, never ground. The report lists every value derived and warns on hard clouds. Total error with each sample held out of the choice of the defaults (8 ISPRS samples, 4 real vendor-classified files): 3.31 % on the ISPRS samples, 0.43 % on the real files (SMRF with PDAL's defaults: 5.75 % and 2.65 %); ISPRS mean at the defaults 3.27 %.</source>
            <translation>يصنّف سحابة نقاط LAS/LAZ إلى أرض (الفئة 2) ونقاط أخرى (الفئة 1) وضوضاء منخفضة (الفئة 7) دون أي معامل يُضبط: مرشح مورفولوجي تدريجي (Pingel et al. 2013) تُشتق خليته وتفاوتات انحداره وارتفاعه من السحابة، ويُطبَّق على التضاريس بعد إزالة انحدارها الإقليمي؛ وتُستعاد قمم التضاريس التي أزالها، ثم تمريرات تعيد بناء التضاريس وتختبر كل نقطة من جديد. تحت غطاء شجري كثيف تُبقى ارتدادات الأرض المنفردة، فلا تصعد التضاريس أبداً إلى الأشجار؛ ويحتفظ الماء المصنف 9 في المدخل بفئته، وتأخذ الرقع المستوية المتفرقة التي تشبه الماء الفئة 1 ولا تكون أرضاً أبداً. يسرد التقرير كل قيمة مشتقة وينبّه على السحب الصعبة. الخطأ الكلي مع استبعاد كل عينة من اختيار القيم الافتراضية (8 عينات ISPRS و4 ملفات حقيقية صنّفها المورّد): ‏3.31 % على عينات ISPRS و0.43 % على الملفات الحقيقية (SMRF بالقيم الافتراضية لـ PDAL: ‏5.75 % و2.65 %)؛ متوسط ISPRS بالقيم الافتراضية 3.27 %.</translation>
        </message>
    </context>
    <context>
        <name>GsdBatchAlgorithm</name>
        <message>
            <source>Table of cameras and distances</source>
            <translation>جدول الكاميرات والمسافات</translation>
        </message>
        <message>
            <source>Round GSD to 0.01 cm/px like the paper</source>
            <translation>تقريب GSD إلى 0.01 سم/بكسل كما في البحث</translation>
        </message>
        <message>
            <source>GSD results</source>
            <translation>نتائج GSD</translation>
        </message>
        <message>
            <source>The table has no 'distance' column (m); columns found: {0}.</source>
            <translation>لا يحتوي الجدول على العمود 'distance' (م)؛ الأعمدة الموجودة: {0}.</translation>
        </message>
        <message>
            <source>Row {row}: unknown camera '{cam}'; known: {known}.</source>
            <translation>السطر {row}: كاميرا غير معروفة '{cam}'؛ المعروفة: {known}.</translation>
        </message>
        <message>
            <source>Row {row}, column '{col}': '{val}' is not a number.</source>
            <translation>السطر {row}، العمود '{col}': القيمة '{val}' ليست رقماً.</translation>
        </message>
        <message>
            <source>Row {row}: missing {cols}; give the columns or a camera preset.</source>
            <translation>السطر {row}: القيم {cols} ناقصة؛ أضف الأعمدة أو حدّد كاميرا معرّفة مسبقاً.</translation>
        </message>
        <message>
            <source>Row {row}: {err}</source>
            <translation>السطر {row}: {err}</translation>
        </message>
        <message>
            <source>Could not write the result table: {0}</source>
            <translation>تعذّرت كتابة جدول النتائج: {0}</translation>
        </message>
        <message>
            <source>Runs the GSD and accuracy calculator for every row of a table (CSV, spreadsheet or any layer) and writes a table with the inputs and all results. A row with an invalid value stops the run with an error naming the row and the column.</source>
            <translation>يشغّل حاسبة GSD والدقة لكل صف في جدول (CSV أو جدول بيانات أو أي طبقة) ويكتب جدولًا بالمدخلات وكل النتائج. الصف ذو القيمة غير الصالحة يوقف التشغيل برسالة خطأ تسمّي الصف والعمود.</translation>
        </message>
        <message>
            <source>Columns (any case): &lt;i&gt;camera&lt;/i&gt; (optional preset key: nikon_p100, dji_p4rtk, dji_p1_35, phaseone_ixm100_80), &lt;i&gt;distance&lt;/i&gt; (m, required), &lt;i&gt;sensor_width&lt;/i&gt; (mm), &lt;i&gt;image_width&lt;/i&gt; (px), &lt;i&gt;focal_length&lt;/i&gt; (mm) — required without a preset — and optionally sensor_height, image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, forward_overlap, side_overlap, stereo_base (units as in the single calculator).</source>
            <translation>الأعمدة (بأي حالة أحرف): &lt;i&gt;camera&lt;/i&gt; (مفتاح إعداد مسبق اختياري: nikon_p100، dji_p4rtk، dji_p1_35، phaseone_ixm100_80)، و&lt;i&gt;distance&lt;/i&gt; (م، إلزامي)، و&lt;i&gt;sensor_width&lt;/i&gt; (مم)، و&lt;i&gt;image_width&lt;/i&gt; (بكسل)، و&lt;i&gt;focal_length&lt;/i&gt; (مم) — إلزامية دون إعداد مسبق — واختياريًا sensor_height، image_height، target_gsd، k_m، k_s، pyramid_level، subsampling_step، observed_sx، observed_sy، observed_sz، observed_sxyz، observed_dense_std، forward_overlap، side_overlap، stereo_base (بالوحدات نفسها كما في الحاسبة المفردة).</translation>
        </message>
        <message>
            <source>Rounds the GSD before the derived quantities, as the paper does.</source>
            <translation>يقرّب GSD قبل حساب الكميات المشتقة، كما يفعل البحث.</translation>
        </message>
        <message>
            <source>The input columns plus gsd_cm, footprint_width_m, sigma_xyz_mm, dense_resolution_cm and every other result.</source>
            <translation>أعمدة المدخلات مضافًا إليها gsd_cm وfootprint_width_m وsigma_xyz_mm وdense_resolution_cm وكل النتائج الأخرى.</translation>
        </message>
        <message>
            <source>GSD calculator over a table of cameras and distances</source>
            <translation>حاسبة GSD لجدول من الكاميرات والمسافات</translation>
        </message>
    </context>
    <context>
        <name>GsdCalculatorAlgorithm</name>
        <message>
            <source>GSD and photogrammetric accuracy calculator</source>
            <translation>حاسبة دقة المسافة الأرضية للبكسل (GSD) والدقة التصويرية</translation>
        </message>
        <message>
            <source>gsd,ground sampling distance,flying height,footprint,accuracy,photogrammetry,drone,flight planning,dense matching</source>
            <translation>gsd,المسافة الأرضية للبكسل,ارتفاع الطيران,البصمة الأرضية,الدقة,المساحة التصويرية,طائرة مسيرة,تخطيط الطيران,المطابقة الكثيفة</translation>
        </message>
        <message>
            <source>Custom (enter the values below)</source>
            <translation>مخصص (أدخل القيم أدناه)</translation>
        </message>
        <message>
            <source>Camera preset</source>
            <translation>كاميرا معرّفة مسبقاً</translation>
        </message>
        <message>
            <source>Camera–object distance / flying height (m)</source>
            <translation>المسافة بين الكاميرا والجسم / ارتفاع الطيران (م)</translation>
        </message>
        <message>
            <source>Sensor height (mm)</source>
            <translation>ارتفاع المستشعر (مم)</translation>
        </message>
        <message>
            <source>Image height (px)</source>
            <translation>ارتفاع الصورة (بكسل)</translation>
        </message>
        <message>
            <source>Target GSD (cm/px)</source>
            <translation>GSD المطلوب (سم/بكسل)</translation>
        </message>
        <message>
            <source>Round GSD to 0.01 cm/px like the paper</source>
            <translation>تقريب GSD إلى 0.01 سم/بكسل كما في البحث</translation>
        </message>
        <message>
            <source>Measurement factor k_m (px)</source>
            <translation>معامل القياس k_m (بكسل)</translation>
        </message>
        <message>
            <source>Safety factor k_s</source>
            <translation>معامل الأمان k_s</translation>
        </message>
        <message>
            <source>Dense matching pyramid level N_p (fraction, or % if checked below)</source>
            <translation>مستوى هرم الصور للمطابقة الكثيفة N_p (كسر، أو نسبة مئوية إذا فُعّل الخيار أدناه)</translation>
        </message>
        <message>
            <source>Pyramid level is a percentage</source>
            <translation>مستوى الهرم نسبة مئوية</translation>
        </message>
        <message>
            <source>Dense matching subsampling step T_s (px)</source>
            <translation>خطوة الاعتيان في المطابقة الكثيفة T_s (بكسل)</translation>
        </message>
        <message>
            <source>Observed σx (mm)</source>
            <translation>σx المرصود (مم)</translation>
        </message>
        <message>
            <source>Observed σy (mm)</source>
            <translation>σy المرصود (مم)</translation>
        </message>
        <message>
            <source>Observed σz (mm)</source>
            <translation>σz المرصود (مم)</translation>
        </message>
        <message>
            <source>Observed σxyz (mm)</source>
            <translation>σxyz المرصود (مم)</translation>
        </message>
        <message>
            <source>Observed dense-cloud std (cm)</source>
            <translation>الانحراف المعياري المرصود للسحابة الكثيفة (سم)</translation>
        </message>
        <message>
            <source>Stereo base B (m) [extension]</source>
            <translation>قاعدة الزوج المجسم B (م) [إضافة]</translation>
        </message>
        <message>
            <source>Forward overlap (%) [extension]</source>
            <translation>التداخل الطولي (%) [إضافة]</translation>
        </message>
        <message>
            <source>Side overlap (%) [extension]</source>
            <translation>التداخل الجانبي (%) [إضافة]</translation>
        </message>
        <message>
            <source>{name} ({unit}) is required with the Custom camera: enter it or choose a camera preset.</source>
            <translation>القيمة {name} ({unit}) مطلوبة مع الكاميرا المخصصة: أدخلها أو اختر كاميرا معرّفة مسبقاً.</translation>
        </message>
        <message>
            <source>Ground sampling distance, footprint and theoretical photogrammetric accuracy of a camera at a distance.</source>
            <translation>المسافة الأرضية للعيّنة والتغطية الأرضية والدقة التصويرية النظرية لكاميرا على مسافة معيّنة.</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Formulas&lt;/b&gt;: GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;); footprint = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;; σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD; σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;; matching step P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;; dense resolution R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;الصيغ&lt;/b&gt;: &lt;span dir="ltr"&gt;GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;)&lt;/span&gt;؛ التغطية = &lt;span dir="ltr"&gt;D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;&lt;/span&gt;؛ خطوة المطابقة &lt;span dir="ltr"&gt;P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;&lt;/span&gt;؛ دقة السحابة الكثيفة &lt;span dir="ltr"&gt;R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD&lt;/span&gt;.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Required with the Custom camera; overrides the preset.</source>
            <translation>مطلوب مع الكاميرا «المخصّصة»؛ ويتقدّم على الإعداد المسبق.</translation>
        </message>
        <message>
            <source>Sensor width (mm) — required with Custom</source>
            <translation>عرض المستشعر (mm) — مطلوب مع «مخصّص»</translation>
        </message>
        <message>
            <source>Image width (px) — required with Custom</source>
            <translation>عرض الصورة (px) — مطلوب مع «مخصّص»</translation>
        </message>
        <message>
            <source>Focal length, true (mm) — required with Custom</source>
            <translation>البعد البؤري الحقيقي (mm) — مطلوب مع «مخصّص»</translation>
        </message>
        <message>
            <source>GSD calculator report</source>
            <translation>تقرير حاسبة GSD</translation>
        </message>
        <message>
            <source>Optional: gives the ratio of the observed to the theoretical accuracy.</source>
            <translation>اختياري: يعطي نسبة الدقة المرصودة إلى الدقة النظرية.</translation>
        </message>
        <message>
            <source>Not in the paper: gives the exposure and line spacing.</source>
            <translation>ليس في البحث: يعطي التباعد بين اللقطات وبين خطوط الطيران.</translation>
        </message>
        <message>
            <source>Computes the ground sampling distance (GSD) and footprint of a camera at a given distance or flying height, and the theoretical accuracy of phototriangulation and of a dense-matching cloud (Al Khalil 2019). The paper's Nikon Coolpix P100 at 5.88 m (sensor width 6.123 mm, image width 3648 px, focal length 4.6 mm) gives a GSD of 0.21455 cm/px, σxyz 1.287 mm and a footprint 7.827 m wide.</source>
            <translation>يحسب دقة المسافة الأرضية للبكسل (GSD) والبصمة الأرضية لكاميرا عند مسافة أو ارتفاع طيران معيّن، والدقة النظرية للتثليث التصويري ولسحابة المطابقة الكثيفة (Al Khalil 2019). كاميرا Nikon Coolpix P100 في البحث على مسافة 5.88 م (عرض المستشعر 6.123 مم، عرض الصورة 3648 بكسل، البعد البؤري 4.6 مم) تعطي GSD قدرها 0.21455 سم/بكسل وσxyz قدرها 1.287 مم وبصمة بعرض 7.827 م.</translation>
        </message>
        <message>
            <source>Fills the sensor, image and focal length values; values you enter override the preset.</source>
            <translation>يملأ قيم المستشعر والصورة والبعد البؤري؛ والقيم التي تدخلها تتقدّم على الإعداد المسبق.</translation>
        </message>
        <message>
            <source>Camera–object distance, or flying height above ground.</source>
            <translation>المسافة بين الكاميرا والجسم، أو ارتفاع الطيران فوق الأرض.</translation>
        </message>
        <message>
            <source>The true focal length, not the 35 mm equivalent.</source>
            <translation>البعد البؤري الحقيقي، لا المكافئ لـ 35 مم.</translation>
        </message>
        <message>
            <source>For the footprint height and the flight spacing.</source>
            <translation>لارتفاع البصمة الأرضية والتباعد بين خطوط الطيران.</translation>
        </message>
        <message>
            <source>Gives the distance that achieves it.</source>
            <translation>يعطي المسافة التي تحققه.</translation>
        </message>
        <message>
            <source>Rounds the GSD before the derived quantities, as the paper does.</source>
            <translation>يقرّب GSD قبل حساب الكميات المشتقة، كما يفعل البحث.</translation>
        </message>
        <message>
            <source>0.13 for an expert operator.</source>
            <translation>0.13 لمشغّل خبير.</translation>
        </message>
        <message>
            <source>A fraction in (0, 1], or a percentage.</source>
            <translation>كسر ضمن (0، 1]، أو نسبة مئوية.</translation>
        </message>
        <message>
            <source>Not in the paper: gives the normal-case σZ.</source>
            <translation>ليس في البحث: يعطي σZ للحالة العادية.</translation>
        </message>
    </context>
    <context>
        <name>IdwDtmAlgorithm</name>
        <message>
            <source>DTM by inverse distance weighting (IDW)</source>
            <translation>استيفاء مقلوب المسافة الموزون (IDW) لنموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>dtm,dem,idw,inverse distance,interpolation,lidar,ground,gdal_grid,invdistnn,raster</source>
            <translation>dtm,dem,idw,مقلوب المسافة,الاستيفاء,ليدار,أرض,gdal_grid,invdistnn,راستر</translation>
        </message>
        <message>
            <source>Power p</source>
            <translation>الأس p</translation>
        </message>
        <message>
            <source>Neighbours (0 = all within radius)</source>
            <translation>عدد الجيران (0 = كل النقاط ضمن نصف القطر)</translation>
        </message>
        <message>
            <source>Search radius (m, 0 = unlimited)</source>
            <translation>نصف قطر البحث (م، 0 = غير محدود)</translation>
        </message>
        <message>
            <source>Minimum points</source>
            <translation>الحد الأدنى لعدد النقاط</translation>
        </message>
        <message>
            <source>IDW DTM</source>
            <translation>نموذج التضاريس الرقمي بطريقة IDW</translation>
        </message>
        <message>
            <source>IDW DTM report</source>
            <translation>تقرير نموذج التضاريس الرقمي بطريقة IDW</translation>
        </message>
        <message>
            <source>Interpolates a terrain raster from the ground points of a LAS/LAZ file by inverse distance weighting (Shepard 1968) over the nearest neighbours of each cell centre. It follows &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; but works in blocks on a KD-tree, so a million points take seconds.</source>
            <translation>يستكمل نموذجًا نقطيًا للتضاريس من نقاط الأرض في ملف LAS/LAZ بطريقة وزن مقلوب المسافة (Shepard 1968) من أقرب الجيران إلى مركز كل خلية. يتبع سلوك &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; لكنه يعمل على كتل باستخدام شجرة KD، فيُعالج مليون نقطة في ثوانٍ.</translation>
        </message>
        <message>
            <source>The seed paper found 3 best (RMSE 0.204 m at 62 GNSS points).</source>
            <translation>وجدت الورقة المرجعية أن القيمة 3 هي الأفضل (RMSE = 0.204 m عند 62 نقطة GNSS).</translation>
        </message>
        <message>
            <source>Nearest points used per cell; 0 = every point within the search radius.</source>
            <translation>عدد أقرب النقاط المستخدمة لكل خلية؛ 0 = كل النقاط داخل نصف قطر البحث.</translation>
        </message>
        <message>
            <source>Only points within this distance are used.</source>
            <translation>تُستخدم النقاط الواقعة ضمن هذه المسافة فقط.</translation>
        </message>
        <message>
            <source>Cells with fewer points within the search radius are nodata.</source>
            <translation>الخلايا التي تقل نقاطها ضمن نصف قطر البحث عن هذا العدد تُترك بلا بيانات.</translation>
        </message>
        <message>
            <source>Points interpolated</source>
            <translation>النقاط المُستوفاة</translation>
        </message>
        <message>
            <source>Cells with a value</source>
            <translation>خلايا ذات قيمة</translation>
        </message>
        <message>
            <source>Nodata cells</source>
            <translation>خلايا بلا بيانات</translation>
        </message>
    </context>
    <context>
        <name>InstallDependenciesAlgorithm</name>
        <message>
            <source>Install the Python packages this toolbox needs</source>
            <translation>تثبيت حزم Python التي يحتاجها صندوق الأدوات هذا</translation>
        </message>
        <message>
            <source>Installs laspy, lazrs, dask and distributed for QGIS's Python into a folder of this QGIS profile.</source>
            <translation>يثبّت laspy وlazrs وdask وdistributed لـ Python الخاص بـ QGIS في مجلد ضمن ملف تعريف QGIS هذا.</translation>
        </message>
        <message>
            <source>install,pip,dependencies,packages,laspy,lazrs,dask,offline,wheels,setup</source>
            <translation>تثبيت,pip,اعتماديات,حزم,laspy,lazrs,dask,دون اتصال,wheels,إعداد</translation>
        </message>
        <message>
            <source>For computers without internet: a folder of wheel files (.whl) downloaded elsewhere with pip download for the same Python version and system. Empty: the package index pip is configured with.</source>
            <translation>للحواسيب غير المتصلة بالإنترنت: مجلد ملفات wheel ‏(.whl) نُزّلت على جهاز آخر بالأمر pip download لإصدار Python نفسه ونظام التشغيل نفسه. فارغ: فهرس الحزم المضبوط في pip.</translation>
        </message>
        <message>
            <source>Folder of wheels (offline installation)</source>
            <translation>مجلد ملفات wheel (تثبيت دون اتصال)</translation>
        </message>
        <message>
            <source>Folder the packages are installed in</source>
            <translation>المجلد الذي ثُبّتت فيه الحزم</translation>
        </message>
        <message>
            <source>Packages installed</source>
            <translation>الحزم المثبّتة</translation>
        </message>
        <message>
            <source>Packages still missing</source>
            <translation>الحزم التي ما زالت ناقصة</translation>
        </message>
        <message>
            <source>pip commands run</source>
            <translation>أوامر pip المنفّذة</translation>
        </message>
        <message>
            <source>Python: {python}</source>
            <translation>Python: {python}</translation>
        </message>
        <message>
            <source>Folder: {folder}</source>
            <translation>المجلد: {folder}</translation>
        </message>
        <message>
            <source>Installed: {packages}</source>
            <translation>ثُبّتت: {packages}</translation>
        </message>
        <message>
            <source>Nothing to install: QGIS's Python already has every package.</source>
            <translation>لا شيء للتثبيت: يحتوي Python الخاص بـ QGIS على كل الحزم.</translation>
        </message>
        <message>
            <source>The LiDAR algorithms need laspy and lazrs, the tile catalog also dask and distributed; QGIS ships the rest (numpy, SciPy, GDAL), and where a QGIS build lacks SciPy it is installed too, for QGIS's own numpy. This installs the versions the toolbox was tested with, only those QGIS's Python lacks, with that Python's pip into a folder of the current QGIS profile: QGIS's own packages are never changed or replaced, and removing the folder undoes it. The log shows every command and everything pip prints.</source>
            <translation>تحتاج خوارزميات ليدار إلى laspy وlazrs، ويحتاج فهرس البلاطات أيضًا إلى dask وdistributed؛ أما الباقي (numpy وSciPy وGDAL) فيأتي مع QGIS، وإن خلا إصدارٌ من QGIS من SciPy ثُبّتت هي أيضًا بما يوافق numpy الخاص بـ QGIS. تثبّت هذه الخوارزمية الإصدارات التي اختُبر بها صندوق الأدوات، وفقط ما ينقص Python الخاص بـ QGIS، باستخدام pip التابع له في مجلد ضمن ملف تعريف QGIS الحالي: لا تُغيَّر حزم QGIS نفسها ولا تُستبدل أبدًا، وحذف المجلد يلغي التثبيت. يعرض السجل كل أمر وكل ما يطبعه pip.</translation>
        </message>
    </context>
    <context>
        <name>KrigingDtmAlgorithm</name>
        <message>
            <source>DTM by kriging (ordinary / universal)</source>
            <translation>الكريغينغ (العادي / الشامل) لنموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>dtm,dem,kriging,variogram,geostatistics,pykrige,interpolation,lidar,variance,cross-validation</source>
            <translation>dtm,dem,كريغينغ,فاريوغرام,الإحصاء الجغرافي,pykrige,الاستيفاء,ليدار,التباين,التحقق المتقاطع</translation>
        </message>
        <message>
            <source>Kriging type</source>
            <translation>نوع الكريغينغ</translation>
        </message>
        <message>
            <source>Ordinary</source>
            <translation>عادي</translation>
        </message>
        <message>
            <source>Universal (linear drift)</source>
            <translation>شامل (انجراف خطي)</translation>
        </message>
        <message>
            <source>Variogram model</source>
            <translation>نموذج الفاريوغرام</translation>
        </message>
        <message>
            <source>Neighbours per cell</source>
            <translation>عدد الجيران لكل خلية</translation>
        </message>
        <message>
            <source>Points for the variogram fit</source>
            <translation>عدد النقاط لمواءمة الفاريوغرام</translation>
        </message>
        <message>
            <source>Lag classes</source>
            <translation>عدد فئات مسافة الإزاحة (lag)</translation>
        </message>
        <message>
            <source>Maximum lag (m, 0 = auto: local scale)</source>
            <translation>أقصى مسافة إزاحة (م، 0 = تلقائي: المقياس المحلي)</translation>
        </message>
        <message>
            <source>Cross-validation points (0 = off)</source>
            <translation>نقاط التحقق المتقاطع (0 = معطَّل)</translation>
        </message>
        <message>
            <source>Random seed</source>
            <translation>البذرة العشوائية</translation>
        </message>
        <message>
            <source>Kriging DTM</source>
            <translation>نموذج التضاريس الرقمي بطريقة الكريغينغ</translation>
        </message>
        <message>
            <source>Write standard deviation instead of variance</source>
            <translation>كتابة الانحراف المعياري بدلاً من التباين</translation>
        </message>
        <message>
            <source>Kriging variance</source>
            <translation>تباين الكريغينغ</translation>
        </message>
        <message>
            <source>Variogram: {}</source>
            <translation>الفاريوغرام: {}</translation>
        </message>
        <message>
            <source>Variogram nugget (m², empty = fit)</source>
            <translation>الأثر الكتلي للفاريوغرام (م²، فارغ = توفيق)</translation>
        </message>
        <message>
            <source>Variogram sill, nugget included (m², empty = fit)</source>
            <translation>عتبة الفاريوغرام شاملة الأثر الكتلي (م²، فارغ = توفيق)</translation>
        </message>
        <message>
            <source>Variogram practical range (m, empty = fit)</source>
            <translation>المدى العملي للفاريوغرام (م، فارغ = توفيق)</translation>
        </message>
        <message>
            <source>Linear variogram slope (m²/m)</source>
            <translation>ميل الفاريوغرام الخطي (م²/م)</translation>
        </message>
        <message>
            <source>Power variogram scale</source>
            <translation>مقياس فاريوغرام القوة</translation>
        </message>
        <message>
            <source>Power variogram exponent (0–2)</source>
            <translation>أس فاريوغرام القوة (0–2)</translation>
        </message>
        <message>
            <source>Variogram parameters as text (old form)</source>
            <translation>معاملات الفاريوغرام نصاً (الصيغة القديمة)</translation>
        </message>
        <message>
            <source>Kriging DTM report</source>
            <translation>تقرير نموذج التضاريس الرقمي بطريقة الكريغينغ</translation>
        </message>
        <message>
            <source>Kriges the ground points of a LAS/LAZ file onto a raster (ordinary kriging, or universal kriging with a linear drift) and can also write the kriging variance. The variogram is fitted on a random sample or given by you, and each cell is kriged from its nearest points, so a million points take about a minute.</source>
            <translation>يطبّق الكريغينغ على نقاط الأرض في ملف LAS/LAZ لإنتاج نموذج نقطي (كريغينغ عادي، أو كريغينغ شامل مع انجراف خطي)، ويمكنه كتابة تباين الكريغينغ أيضًا. يُوفَّق الفاريوغرام على عيّنة عشوائية أو تُدخله أنت، وتُقدَّر كل خلية من أقرب نقاطها، فيستغرق مليون نقطة نحو دقيقة.</translation>
        </message>
        <message>
            <source>Give nugget, sill and range to skip the fit; the sill includes the nugget.</source>
            <translation>أدخل الأثر الكتلي والعتبة والمدى لتجاوز التوفيق؛ العتبة تشمل الأثر الكتلي.</translation>
        </message>
        <message>
            <source>Linear model only.</source>
            <translation>للنموذج الخطي فقط.</translation>
        </message>
        <message>
            <source>Power model only.</source>
            <translation>لنموذج القوة فقط.</translation>
        </message>
        <message>
            <source>Local kriging: the mean is re-estimated in every neighbourhood; as many neighbours as points (up to 6000) gives global kriging, identical to PyKrige.</source>
            <translation>كريغينغ محلي: يُعاد تقدير المتوسط في كل جوار؛ وإذا ساوى عدد الجيران عدد النقاط (حتى 6000) صار كريغينغًا شاملًا مطابقًا لـ PyKrige.</translation>
        </message>
        <message>
            <source>0 = three times the typical distance to the farthest neighbour used; for a field-scale fit give about half the extent.</source>
            <translation>0 = ثلاثة أضعاف المسافة المعتادة إلى أبعد جار مستخدم؛ للتوفيق على مقياس الحقل كله أدخل نحو نصف الامتداد.</translation>
        </message>
        <message>
            <source>Leave-one-out check on this many random points; an RMS standardised error near 1 means realistic variances.</source>
            <translation>تحقق بالاستبعاد الفردي على هذا العدد من النقاط العشوائية؛ جذر متوسط مربع الخطأ المعياري القريب من 1 يعني تباينات واقعية.</translation>
        </message>
        <message>
            <source>Makes the sample of the variogram fit reproducible.</source>
            <translation>يجعل عيّنة توفيق الفاريوغرام قابلة للتكرار.</translation>
        </message>
        <message>
            <source>In m², or in m as a standard deviation.</source>
            <translation>بوحدة m²، أو بوحدة m كانحراف معياري.</translation>
        </message>
        <message>
            <source>Nugget</source>
            <translation>الأثر الكتلي (Nugget)</translation>
        </message>
        <message>
            <source>Sill</source>
            <translation>العتبة (Sill)</translation>
        </message>
        <message>
            <source>Range</source>
            <translation>المدى</translation>
        </message>
        <message>
            <source>Points kriged</source>
            <translation>النقاط المستخدمة في الكريجينغ</translation>
        </message>
        <message>
            <source>Cells with a value</source>
            <translation>خلايا ذات قيمة</translation>
        </message>
        <message>
            <source>Cross-validation mean error</source>
            <translation>متوسط الخطأ في التحقق المتقاطع</translation>
        </message>
        <message>
            <source>Cross-validation RMSE</source>
            <translation>RMSE للتحقق المتقاطع</translation>
        </message>
        <message>
            <source>Cross-validation mean standardised error</source>
            <translation>متوسط الخطأ المعياري في التحقق المتقاطع</translation>
        </message>
    </context>
    <context>
        <name>LidarFilterMixin</name>
        <message>
            <source>{} points: {} ground, {} non-ground, {} low outliers; filter {:.1f} s</source>
            <translation>{} نقطة: {} أرضية، {} غير أرضية، {} قيم شاذة منخفضة؛ الترشيح {:.1f} ث</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
    </context>
    <context>
        <name>LidarQaAlgorithm</name>
        <message>
            <source>Point density and quality (with parameter advice)</source>
            <translation>كثافة النقاط وجودتها (مع توصيات المعاملات)</translation>
        </message>
        <message>
            <source>Density rasters, gaps, duplicates and noise of a cloud, and the filter window and DTM cell its density supports.</source>
            <translation>شبكات الكثافة والفجوات والنقاط المكررة والضوضاء في سحابة، ونافذة المرشح وخلية نموذج التضاريس التي تسمح بها كثافتها.</translation>
        </message>
        <message>
            <source>density,quality,qa,lasinfo,gaps,duplicates,noise,scan angle,returns,advice,lidar</source>
            <translation>كثافة,جودة,qa,lasinfo,فجوات,مكررات,ضوضاء,زاوية المسح,انعكاسات,توصيات,ليدار</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>حجم الخلية (م)</translation>
        </message>
        <message>
            <source>Ground classes</source>
            <translation>أصناف الأرض</translation>
        </message>
        <message>
            <source>Density rasters</source>
            <translation>شبكات الكثافة</translation>
        </message>
        <message>
            <source>Checks a LAS/LAZ cloud before processing: density of all, last and ground returns, gaps without ground, duplicates, noise share and scan angles. It then states which settings the density supports: ground filter window, DTM cell size, LOD1 only below 1 pt/m², and the radius and tile of the slope-based and LSQ filters.</source>
            <translation>يفحص سحابة LAS/LAZ قبل المعالجة: كثافة كل الانعكاسات والأخيرة منها وانعكاسات الأرض، والفجوات الخالية من الأرض، والنقاط المكررة، ونسبة الضجيج، وزوايا المسح. ثم يبيّن الإعدادات التي تدعمها الكثافة: نافذة مرشح الأرض، وحجم خلية DTM، وLOD1 فقط دون 1 pt/m²، ونصف قطر مرشح الانحدار وبلاطة مرشح LSQ.</translation>
        </message>
        <message>
            <source>In a projected CRS (metres); a cloud in degrees is refused.</source>
            <translation>بنظام إحداثيات مُسقَط (بالأمتار)؛ وتُرفض السحابة بالدرجات.</translation>
        </message>
        <message>
            <source>GeoTIFF with four bands: all returns, last returns, ground (pts/m²) and gap (1/0).</source>
            <translation>ملف GeoTIFF بأربع حزم: كل الانعكاسات، والانعكاسات الأخيرة، والأرض (pts/m²)، والفجوة (1/0).</translation>
        </message>
        <message>
            <source>Maps, histograms and the advice.</source>
            <translation>خرائط ومدرّجات تكرارية والتوصيات.</translation>
        </message>
        <message>
            <source>Point density and quality report</source>
            <translation>تقرير كثافة النقاط وجودتها</translation>
        </message>
        <message>
            <source>Density of all returns (pts/m²)</source>
            <translation>كثافة كل الانعكاسات (نقطة/م²)</translation>
        </message>
        <message>
            <source>Ground density (pts/m²)</source>
            <translation>كثافة نقاط الأرض (نقطة/م²)</translation>
        </message>
        <message>
            <source>Share of cells without ground</source>
            <translation>نسبة الخلايا بلا أرض</translation>
        </message>
        <message>
            <source>Duplicate points</source>
            <translation>النقاط المكررة</translation>
        </message>
        <message>
            <source>Noise share</source>
            <translation>نسبة الضوضاء</translation>
        </message>
        <message>
            <source>Ground filter window (m)</source>
            <translation>نافذة مرشح الأرض (م)</translation>
        </message>
        <message>
            <source>Recommended DTM cell (m)</source>
            <translation>خلية نموذج التضاريس الموصى بها (م)</translation>
        </message>
    </context>
    <context>
        <name>LidarToDtmAlgorithm</name>
        <message>
            <source>LiDAR to DTM with accuracy</source>
            <translation>من LiDAR إلى نموذج تضاريس رقمي مع الدقة</translation>
        </message>
        <message>
            <source>lidar,ground,filter,dtm,dem,idw,accuracy,rmse,check points,chain,all-or-nothing</source>
            <translation>ليدار,أرض,مرشح,نموذج تضاريس,dem,idw,دقة,rmse,نقاط تحقق,سلسلة,الكل أو لا شيء</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>حجم خلية نموذج التضاريس (م)</translation>
        </message>
        <message>
            <source>IDW power</source>
            <translation>أس IDW</translation>
        </message>
        <message>
            <source>IDW neighbours</source>
            <translation>عدد جيران IDW</translation>
        </message>
        <message>
            <source>Fill data gaps in the DTM (interpolate far from ground points)</source>
            <translation>ملء فجوات البيانات في نموذج التضاريس (الاستكمال بعيدًا عن نقاط الأرض)</translation>
        </message>
        <message>
            <source>CRS override for a cloud without a CRS record</source>
            <translation>نظام إحداثيات بديل لسحابة بلا سجل نظام إحداثيات</translation>
        </message>
        <message>
            <source>Check points (CSV/TXT file: id,x,y,z)</source>
            <translation>نقاط التحقق (ملف CSV/TXT: ‏id,x,y,z)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>نموذج التضاريس الرقمي (DTM)</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>بواقي نقاط التحقق</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>تقرير دقة نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>تقرير مرشح الأرض</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>تقرير نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط الأرض</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>سحابة النقاط لا تحوي سجل نظام إحداثيات ولم يُحدَّد نظام إحداثيات؛ اضبط المعامل CRS (مثلاً EPSG:32632). لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>None of the {n} check points lies within the point cloud's extent (x {x0:.1f}–{x1:.1f}, y {y0:.1f}–{y1:.1f}); are they in another CRS? No output was written.</source>
            <translation>لا تقع أي من نقاط التحقق الـ {n} ضمن امتداد سحابة النقاط (x ‏{x0:.1f}–{x1:.1f}، y ‏{y0:.1f}–{y1:.1f})؛ هل هي في نظام إحداثيات آخر؟ لم يُكتب أي ناتج.</translation>
        </message>
        <message>
            <source>Choose the point cloud (a .las or .laz file).</source>
            <translation>اختر سحابة النقاط (ملف ‎.las‏ أو ‎.laz‏).</translation>
        </message>
        <message>
            <source>Choose an output file for {}.</source>
            <translation>اختر ملف ناتج لـ {}.</translation>
        </message>
        <message>
            <source>Cell size must be &gt; 0 (metres); give e.g. 1.0.</source>
            <translation>يجب أن يكون حجم الخلية &gt; 0 (أمتار)؛ أعطِ مثلًا 1.0.</translation>
        </message>
        <message>
            <source>The ground filter found no ground point; no DTM can be interpolated. No output was written.</source>
            <translation>لم يجد مرشح الأرض أي نقطة أرض؛ لا يمكن استكمال نموذج تضاريس. لم يُكتب أي ناتج.</translation>
        </message>
        <message>
            <source>Classifies the ground of a LiDAR point cloud, interpolates an IDW DTM from the ground points and measures its accuracy against check points, in one step. It writes all its outputs or none, and its results equal those of the three algorithms run one after another.</source>
            <translation>يصنّف أرض سحابة نقاط LiDAR، ويستكمل نموذج تضاريس رقميًا بطريقة IDW من نقاط الأرض، ويقيس دقته مقابل نقاط تحقق، في خطوة واحدة. يكتب كل مخرجاته أو لا شيء، ونتائجه تطابق نتائج الخوارزميات الثلاث مشغّلةً الواحدة تلو الأخرى.</translation>
        </message>
        <message>
            <source>In a projected CRS (metres).</source>
            <translation>بنظام إحداثيات مُسقَط (بالأمتار).</translation>
        </message>
        <message>
            <source>Give the layer or the file; duplicates and points outside the cloud's extent are refused before anything is written.</source>
            <translation>أدخل الطبقة أو الملف؛ وتُرفض النقاط المكررة والواقعة خارج امتداد السحابة قبل كتابة أي شيء.</translation>
        </message>
        <message>
            <source>Classified by the recommended ground filter (the improved least-squares filter where it is not installed).</source>
            <translation>مصنّفة بمرشح الأرض الموصى به (أو بمرشح المربعات الصغرى المحسَّن حيث لا يكون مثبّتًا).</translation>
        </message>
        <message>
            <source>The seed paper found 3 best (RMSE 0.204 m at 62 GNSS points).</source>
            <translation>وجدت الورقة المرجعية أن القيمة 3 هي الأفضل (RMSE = 0.204 m عند 62 نقطة GNSS).</translation>
        </message>
    </context>
    <context>
        <name>LsqGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (least-squares polynomial)</source>
            <translation>مرشح نقاط الأرض (متعدد حدود بالمربعات الصغرى)</translation>
        </message>
        <message>
            <source>lidar,ground,filter,bare earth,dtm,classification,least squares,polynomial,tiles,las,laz,isprs</source>
            <translation>ليدار,أرض,مرشح,الأرض العارية,dtm,تصنيف,المربعات الصغرى,متعدد الحدود,بلاطات,las,laz,isprs</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Polynomial order (1 or 2)</source>
            <translation>درجة متعدد الحدود (1 أو 2)</translation>
        </message>
        <message>
            <source>Tile size (m)</source>
            <translation>حجم البلاطة (م)</translation>
        </message>
        <message>
            <source>Threshold T (m)</source>
            <translation>العتبة T (م)</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>النمط</translation>
        </message>
        <message>
            <source>Faithful (the paper)</source>
            <translation>مطابق (طريقة البحث)</translation>
        </message>
        <message>
            <source>Improved (ours, beyond the paper)</source>
            <translation>محسَّن (من إضافتنا، يتجاوز البحث)</translation>
        </message>
        <message>
            <source>Maximum iterations per tile</source>
            <translation>الحد الأقصى للتكرارات في كل بلاطة</translation>
        </message>
        <message>
            <source>Stop tolerance on min/max/mean/std (m)</source>
            <translation>سماحية التوقف على الأدنى/الأعلى/المتوسط/الانحراف المعياري (م)</translation>
        </message>
        <message>
            <source>Random fitting subset per tile (points, 0 = all)</source>
            <translation>مجموعة جزئية عشوائية للمواءمة في كل بلاطة (نقاط، 0 = الكل)</translation>
        </message>
        <message>
            <source>Random seed of the subset</source>
            <translation>البذرة العشوائية للمجموعة الجزئية</translation>
        </message>
        <message>
            <source>Minimum points per tile (0 = 3 × coefficients)</source>
            <translation>الحد الأدنى للنقاط في البلاطة (0 = 3 × عدد معاملات متعدد الحدود)</translation>
        </message>
        <message>
            <source>Under-populated tiles</source>
            <translation>البلاطات قليلة النقاط</translation>
        </message>
        <message>
            <source>Borrow the nearest fitted tile's surface</source>
            <translation>استعارة سطح أقرب بلاطة مُوائَمة</translation>
        </message>
        <message>
            <source>Leave their points unclassified (class 0)</source>
            <translation>ترك نقاطها دون تصنيف (الصنف 0)</translation>
        </message>
        <message>
            <source>Rejection</source>
            <translation>الاستبعاد</translation>
        </message>
        <message>
            <source>Re-weighted each iteration (a point may return)</source>
            <translation>إعادة الترجيح في كل تكرار (قد تعود النقطة)</translation>
        </message>
        <message>
            <source>Cumulative (a rejected point stays out)</source>
            <translation>تراكمي (النقطة المستبعدة تبقى مستبعدة)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>Ground points only</source>
            <translation>نقاط الأرض فقط</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط الأرض</translation>
        </message>
        <message>
            <source>Other (object) points</source>
            <translation>النقاط الأخرى (الأجسام)</translation>
        </message>
        <message>
            <source>Low-noise points</source>
            <translation>نقاط الضوضاء المنخفضة</translation>
        </message>
        <message>
            <source>Unclassified points</source>
            <translation>النقاط غير المصنَّفة</translation>
        </message>
        <message>
            <source>Tiles</source>
            <translation>البلاطات</translation>
        </message>
        <message>
            <source>Points per second</source>
            <translation>نقطة في الثانية</translation>
        </message>
        <message>
            <source>Choose an output file for the classified cloud (OUTPUT, .laz or .las).</source>
            <translation>اختر ملف إخراج للسحابة المصنَّفة (OUTPUT، بالامتداد .laz أو .las).</translation>
        </message>
        <message>
            <source>Reading {p}</source>
            <translation>جارٍ قراءة {p}</translation>
        </message>
        <message>
            <source>{step}: {n} points kept, ZMin {a:.2f}, ZMax {b:.2f}, ZMean {m:.2f}, σ {s:.2f}; tiles iterating: {t}</source>
            <translation>{step}: أُبقيت {n} نقطة، ZMin {a:.2f}، ZMax {b:.2f}، ZMean {m:.2f}، σ {s:.2f}؛ بلاطات قيد التكرار: {t}</translation>
        </message>
        <message>
            <source>Ground {g}, other {o}, low noise {z}, unclassified {u}; {t} tiles; {s:.1f} s</source>
            <translation>أرض {g}، أخرى {o}، ضوضاء منخفضة {z}، غير مصنَّفة {u}؛ {t} بلاطة؛ {s:.1f} ث</translation>
        </message>
        <message>
            <source>Per-tile iteration statistics (CSV)</source>
            <translation>إحصاءات التكرارات لكل بلاطة (CSV)</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>ملفات CSV (*.csv)</translation>
        </message>
        <message>
            <source>Separates bare-earth points from buildings and vegetation in an airborne LiDAR cloud by fitting least-squares polynomial surfaces per square tile (Damascus Univ. J. Eng. Sci. 29(2), 2013). Points more than the threshold above the surface are dropped and the fit repeated until the height statistics settle; the rest become ground (class 2), the others class 1.</source>
            <translation>يفصل نقاط سطح الأرض العاري عن المباني والنباتات في سحابة LiDAR جوية بتوفيق سطوح متعددة الحدود بالمربعات الصغرى لكل بلاطة مربعة (مجلة جامعة دمشق للعلوم الهندسية 29(2)، 2013). تُستبعد النقاط التي تعلو السطح بأكثر من العتبة ويُعاد التوفيق حتى تستقر إحصاءات الارتفاع؛ فتصبح البقية أرضًا (الفئة 2) والأخرى الفئة 1.</translation>
        </message>
        <message>
            <source>1 = plane, 2 = quadratic surface (better on every sample of the paper).</source>
            <translation>1 = مستوٍ، 2 = سطح تربيعي (أفضل في كل عيّنات الورقة).</translation>
        </message>
        <message>
            <source>Larger than the largest building, so that every tile holds ground (the paper: 100 m for large buildings, 50 m for small ones).</source>
            <translation>أكبر من أكبر مبنى، كي تحوي كل بلاطة أرضًا (الورقة: 100 m للمباني الكبيرة، و50 m للصغيرة).</translation>
        </message>
        <message>
            <source>0.5–1.0 m, larger on steeper terrain.</source>
            <translation>من 0.5 إلى 1.0 m، وأكبر في التضاريس الأشد انحدارًا.</translation>
        </message>
        <message>
            <source>Faithful follows the paper. Improved (this toolbox's extension) fits coarse-to-fine overlapping tiles with a slope-dependent threshold: mean total error on the ISPRS samples 8.9 % → about 4.9 %, at about 15 times the time.</source>
            <translation>الوفيّ يتبع الورقة. المحسَّن (امتداد من هذه الأداة) يوفّق بلاطات متداخلة من الخشن إلى الدقيق بعتبة تتبع الانحدار: متوسط الخطأ الكلي على عيّنات ISPRS ‏8.9 % ← نحو 4.9 %، بنحو 15 ضعف الوقت.</translation>
        </message>
        <message>
            <source>Points far below their neighbours (multipath) get class 7 and take no part in the fit.</source>
            <translation>النقاط الواقعة أدنى بكثير من جيرانها (تعدد المسارات) تأخذ الفئة 7 ولا تشارك في التوفيق.</translation>
        </message>
        <message>
            <source>The paper used 5000; every point is still classified.</source>
            <translation>استخدمت الورقة 5000؛ وتُصنَّف كل النقاط مع ذلك.</translation>
        </message>
        <message>
            <source>Tiles with too few points borrow the nearest fitted surface, or their points stay class 0.</source>
            <translation>البلاطات القليلة النقاط تستعير أقرب سطح موفَّق، أو تبقى نقاطها في الفئة 0.</translation>
        </message>
        <message>
            <source>Re-weighted: a dropped point may come back when the surface moves; cumulative: dropped for good.</source>
            <translation>إعادة الترجيح: قد تعود نقطة مستبعدة حين يتحرك السطح؛ تراكمي: تُستبعد نهائيًا.</translation>
        </message>
        <message>
            <source>Every attribute, point format, scales, offsets, VLRs and CRS are copied unchanged; any earlier classification is replaced.</source>
            <translation>تُنسخ كل الخصائص وصيغة النقاط والمقاييس والإزاحات وسجلات VLR ونظام الإحداثيات دون تغيير؛ ويُستبدل أي تصنيف سابق.</translation>
        </message>
        <message>
            <source>Class counts, the per-iteration statistics of the paper's tables, a tile map and the speed.</source>
            <translation>أعداد الفئات، وإحصاءات كل تكرار كما في جداول الورقة، وخريطة البلاطات، والسرعة.</translation>
        </message>
        <message>
            <source>LSQ ground filter report</source>
            <translation>تقرير مرشح الأرض بالمربعات الصغرى (LSQ)</translation>
        </message>
        <message>
            <source>Improved is the default: its total error is lower on each of the 8 ISPRS samples (mean 7.2 % against 21.3 %; 9.5 % against 29.6 % on the four it was not tuned on).</source>
            <translation>المحسَّن هو الافتراضي: خطؤه الكلي أدنى في كل عينة من عينات ISPRS الثماني (المتوسط 7.2 % مقابل 21.3 %؛ و9.5 % مقابل 29.6 % على العينات الأربع التي لم يُضبط عليها).</translation>
        </message>
    </context>
    <context>
        <name>PtdGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (progressive TIN densification)</source>
            <translation>مرشح الأرض (التكثيف التدريجي لشبكة TIN)</translation>
        </message>
        <message>
            <source>Axelsson's progressive TIN densification ground filter.</source>
            <translation>مرشح الأرض بالتكثيف التدريجي لشبكة TIN (Axelsson).</translation>
        </message>
        <message>
            <source>Cell (m)</source>
            <translation>الخلية (م)</translation>
        </message>
        <message>
            <source>Parcel size, &gt; largest building (m)</source>
            <translation>حجم القطعة، &gt; أكبر مبنى (م)</translation>
        </message>
        <message>
            <source>Distance to facet (m)</source>
            <translation>المسافة إلى الوجه (م)</translation>
        </message>
        <message>
            <source>Angle to vertices (degrees)</source>
            <translation>الزاوية إلى الرؤوس (درجات)</translation>
        </message>
        <message>
            <source>Final distance (m)</source>
            <translation>المسافة النهائية (م)</translation>
        </message>
        <message>
            <source>Low-noise depth (m)</source>
            <translation>عمق الضجيج المنخفض (م)</translation>
        </message>
        <message>
            <source>Shortest facet edge (m)</source>
            <translation>أقصر ضلع للوجه (م)</translation>
        </message>
        <message>
            <source>Iteration cap</source>
            <translation>الحد الأقصى للتكرارات</translation>
        </message>
        <message>
            <source>PTD: parcels {} m, distance {} m, angle {}°</source>
            <translation>PTD: قطع {} م، مسافة {} م، زاوية {}°</translation>
        </message>
        <message>
            <source>Cliff-aware mirroring</source>
            <translation>انعكاس مراعٍ للجروف</translation>
        </message>
        <message>
            <source>Lowest point per cell for the step filter and the seeds.</source>
            <translation>أدنى نقطة في كل خلية لمرشح الدرجات وللبذور.</translation>
        </message>
        <message>
            <source>Densification limit: distance of a point to its facet.</source>
            <translation>حدّ التكثيف: بُعد النقطة عن وجه المثلث.</translation>
        </message>
        <message>
            <source>Densification limit: angle under which a point is seen from the facet's vertices.</source>
            <translation>حدّ التكثيف: الزاوية التي تُرى بها النقطة من رؤوس الوجه.</translation>
        </message>
        <message>
            <source>Points this close to the final TIN are ground.</source>
            <translation>النقاط القريبة إلى هذا الحد من شبكة TIN النهائية أرض.</translation>
        </message>
        <message>
            <source>Points deeper below the final TIN get class 7.</source>
            <translation>النقاط الأعمق من ذلك تحت شبكة TIN النهائية تأخذ الفئة 7.</translation>
        </message>
        <message>
            <source>Points in a TIN facet that spans a cliff (steeper than 45° and higher than the distance to facet) are mirrored through nearby TIN vertices and accepted when the mirror lies on the cliff foot or top within the final distance, so the ground right at the cliff edge is kept.</source>
            <translation>النقاط الواقعة في وجه من شبكة TIN يمتد عبر جرف (أشد انحداراً من 45° وأعلى من المسافة إلى الوجه) تُعكس عبر رؤوس الشبكة القريبة وتُقبل إذا وقع انعكاسها على قاعدة الجرف أو قمته ضمن المسافة النهائية، فتُحفظ الأرض عند حافة الجرف تماماً.</translation>
        </message>
        <message>
            <source>&lt;p&gt;Reference: Axelsson, P. (2000). &lt;cite&gt;DEM generation from laser scanner data using adaptive TIN models&lt;/cite&gt;. IAPRS XXXIII-B4, 110–117.&lt;/p&gt;</source>
            <translation>&lt;p&gt;المرجع: &lt;bdi dir="ltr"&gt;Axelsson, P. (2000). &lt;cite&gt;DEM generation from laser scanner data using adaptive TIN models&lt;/cite&gt;. IAPRS XXXIII-B4, 110–117.&lt;/bdi&gt;&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Larger than the largest building.</source>
            <translation>أكبر من أكبر مبنى.</translation>
        </message>
        <message>
            <source>A parcel's seed is its lowest point not more than the seed depth below this quantile of the parcel's lowest points per cell, so a cluster of low outliers never seeds the TIN.</source>
            <translation>بذرة القطعة هي أدنى نقطة فيها لا تقع تحت هذا المئين من أدنى نقاط خلايا القطعة بأكثر من عمق البذرة، فلا تصير مجموعة من القيم الشاذة المنخفضة بذرةً لشبكة TIN أبدًا.</translation>
        </message>
        <message>
            <source>See the seed quantile.</source>
            <translation>انظر مئين البذرة.</translation>
        </message>
        <message>
            <source>The lowest point per cell of this size is a candidate of the TIN; every other point is classified by its distance to the final TIN (0 = every point).</source>
            <translation>أدنى نقطة في كل خلية بهذا الحجم نقطة محتملة لشبكة TIN؛ وتُصنَّف كل نقطة أخرى بمسافتها إلى شبكة TIN النهائية (0 = كل النقاط).</translation>
        </message>
        <message>
            <source>Seed quantile (%)</source>
            <translation>مئين البذرة (%)</translation>
        </message>
        <message>
            <source>Seed depth (m)</source>
            <translation>عمق البذرة (م)</translation>
        </message>
        <message>
            <source>Candidate cell (m)</source>
            <translation>خلية النقاط المحتملة (م)</translation>
        </message>
        <message>
            <source>Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) by progressive TIN densification (Axelsson 2000): the lowest trusted point of each parcel larger than the largest building seeds a TIN, which takes the candidates (the lowest point per candidate cell) close enough to its facets until none is added; every other point is ground when it lies close to the final TIN. Its mean total error on the 8 ISPRS samples is 4.55 % at the defaults (Axelsson published 4.82 % over all 15 samples): use the recommended ground filter unless you need a TIN filter.</source>
            <translation>يصنّف سحابة نقاط LAS/LAZ إلى أرض (الفئة 2) ونقاط أخرى (الفئة 1) وضوضاء منخفضة (الفئة 7) بالتكثيف التدريجي لشبكة المثلثات TIN (Axelsson 2000): أدنى نقطة موثوقة في كل قطعة أكبر من أكبر مبنى تكون بذرةً لشبكة TIN، تضم النقاط المحتملة (أدنى نقطة في كل خلية للنقاط المحتملة) القريبة بما يكفي من أوجهها حتى لا تُضاف أي نقطة؛ وكل نقطة أخرى أرض إذا كانت قريبة من شبكة TIN النهائية. متوسط خطئه الكلي على عينات ISPRS الثماني 4.55 % بالقيم الافتراضية (نشر Axelsson ‏4.82 % على العينات الخمس عشرة كلها): استخدم مرشح الأرض المُوصى به ما لم تحتج إلى مرشح TIN.</translation>
        </message>
    </context>
    <context>
        <name>PublishOutputsAlgorithm</name>
        <message>
            <source>Publish chain outputs</source>
            <translation>نشر مخرجات السلسلة</translation>
        </message>
        <message>
            <source>Classified point cloud to publish</source>
            <translation>سحابة النقاط المصنفة المراد نشرها</translation>
        </message>
        <message>
            <source>Ground filter report to publish</source>
            <translation>تقرير مرشح الأرض المراد نشره</translation>
        </message>
        <message>
            <source>DTM to publish</source>
            <translation>نموذج التضاريس الرقمي المراد نشره</translation>
        </message>
        <message>
            <source>DTM report to publish</source>
            <translation>تقرير نموذج التضاريس الرقمي المراد نشره</translation>
        </message>
        <message>
            <source>Check-point residuals to publish</source>
            <translation>بواقي نقاط التحقق المراد نشرها</translation>
        </message>
        <message>
            <source>DTM accuracy report to publish</source>
            <translation>تقرير دقة نموذج التضاريس الرقمي المراد نشره</translation>
        </message>
        <message>
            <source>Point cloud of the chain (never overwritten)</source>
            <translation>سحابة نقاط السلسلة (لا يُكتب فوقها أبدًا)</translation>
        </message>
        <message>
            <source>Check point file of the chain (never overwritten)</source>
            <translation>ملف نقاط التحقق للسلسلة (لا يُكتب فوقه أبدًا)</translation>
        </message>
        <message>
            <source>Check point layer of the chain (never overwritten)</source>
            <translation>طبقة نقاط التحقق للسلسلة (لا يُكتب فوقها أبدًا)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>تقرير مرشح الأرض</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>نموذج التضاريس الرقمي (DTM)</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>تقرير نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>بواقي نقاط التحقق</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>تقرير دقة نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Published {path}</source>
            <translation>نُشر {path}</translation>
        </message>
        <message>
            <source>Copies the files written by the earlier steps of a model to their destinations, all of them or none: it is the last step of the model 'LiDAR to DTM with accuracy', so a destination that cannot be written leaves no classified cloud, DTM or report anywhere. Every destination is checked against the model's inputs, the files to publish and the other destinations first; one in another format than its file (.las for a .laz cloud) is converted.</source>
            <translation>ينسخ الملفات التي كتبتها الخطوات السابقة في النموذج إلى وجهاتها، جميعها أو لا شيء: إنها الخطوة الأخيرة في النموذج 'من LiDAR إلى نموذج تضاريس مع الدقة'، لذا فإن وجهة يتعذّر الكتابة فيها لا تترك سحابة مصنفة ولا نموذج تضاريس ولا تقريرًا في أي مكان. تُفحص كل وجهة أولًا مقابل مدخلات النموذج والملفات المراد نشرها والوجهات الأخرى؛ والوجهة بصيغة غير صيغة ملفها (.las لسحابة .laz) تُحوَّل.</translation>
        </message>
        <message>
            <source>Unset: this file is not published.</source>
            <translation>إن لم يُحدَّد: لا يُنشر هذا الملف.</translation>
        </message>
        <message>
            <source>Never overwritten: checked against every destination.</source>
            <translation>لا يُكتب فوقه أبدًا: يُفحص مقابل كل وجهة.</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>%1 [optional]</source>
            <translation>%1 [اختياري]</translation>
        </message>
    </context>
    <context>
        <name>RectifyBatchAlgorithm</name>
        <message>
            <source>Rectify a folder of images with GCPs (batch)</source>
            <translation>تصحيح مجلد من المرئيات بنقاط الضبط (دفعة)</translation>
        </message>
        <message>
            <source>Warps every image of a folder with its .points file and summarises the accuracy in one table.</source>
            <translation>يصحّح كل مرئية في المجلد بملف ‎.points‎ الخاص بها ويلخّص الدقة في جدول واحد.</translation>
        </message>
        <message>
            <source>georeference,gcp,batch,folder,rectification,warp,rms</source>
            <translation>georeference,gcp,batch,folder,rectification,warp,rms,إسناد جغرافي,دفعة,مجلد,تصحيح</translation>
        </message>
        <message>
            <source>Folder of images with .points files</source>
            <translation>مجلد المرئيات مع ملفات .points</translation>
        </message>
        <message>
            <source>Resampling</source>
            <translation>إعادة الاعتيان</translation>
        </message>
        <message>
            <source>Folder of rectified images</source>
            <translation>مجلد المرئيات المصحّحة</translation>
        </message>
        <message>
            <source>Summary table</source>
            <translation>جدول الملخص</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>ملفات CSV (*.csv)</translation>
        </message>
        <message>
            <source>Rectifies every image of a folder that has its QGIS Georeferencer .points file next to it, with a fixed transformation or the one recommended for each image. It writes one summary table with the transformation, RMS_T, the check or leave-one-out error and the verdict of every image.</source>
            <translation>يصحّح كل صورة في مجلد بجانبها ملف ‎.points‎ من المُرجِع الجغرافي في QGIS، بتحويل ثابت أو بالتحويل الموصى به لكل صورة. ويكتب جدول ملخص واحدًا فيه التحويل وRMS_T وخطأ التحقق أو الاستبعاد الفردي والحكم لكل صورة.</translation>
        </message>
        <message>
            <source>Each image with its .points file next to it (scan.tif + scan.tif.points).</source>
            <translation>كل صورة وبجانبها ملف ‎.points‎ الخاص بها (scan.tif + scan.tif.points).</translation>
        </message>
        <message>
            <source>The last choice picks the recommended transformation for each image.</source>
            <translation>الخيار الأخير يختار التحويل الموصى به لكل صورة.</translation>
        </message>
        <message>
            <source>One rectified GeoTIFF per image, each written all or nothing.</source>
            <translation>ملف GeoTIFF مصحّح لكل صورة، يُكتب كاملًا أو لا يُكتب.</translation>
        </message>
        <message>
            <source>Batch rectification report</source>
            <translation>تقرير التصحيح الدفعي</translation>
        </message>
        <message>
            <source>Images found</source>
            <translation>الصور التي عُثر عليها</translation>
        </message>
        <message>
            <source>Images rectified</source>
            <translation>الصور المصحّحة</translation>
        </message>
        <message>
            <source>{image}: {kind}, RMS_T {rms:.4f}, {basis} RMS_T {honest:.4f}, {verdict} → {output}</source>
            <translation>{image}: {kind}، RMS_T {rms:.4f}، RMS_T ({basis}) {honest:.4f}، {verdict} ← {output}</translation>
        </message>
    </context>
    <context>
        <name>RectifyGcpAlgorithm</name>
        <message>
            <source>georeference,georeferencer,gcp,ground control points,polynomial,rectification,warp,gdalwarp,rms,accuracy</source>
            <translation>إسناد جغرافي,georeferencer,gcp,نقاط الضبط الأرضي,متعدد الحدود,تصحيح هندسي,warp,gdalwarp,rms,الدقة</translation>
        </message>
        <message>
            <source>Target CRS [default: the GCP CRS]</source>
            <translation>نظام الإحداثيات الهدف [الافتراضي: نظام إحداثيات نقاط الضبط]</translation>
        </message>
        <message>
            <source>Resampling</source>
            <translation>إعادة الاعتيان</translation>
        </message>
        <message>
            <source>Output resolution (target CRS units) [default: GR]</source>
            <translation>دقة تمييز المخرج (بوحدات نظام الإحداثيات الهدف) [الافتراضي: GR]</translation>
        </message>
        <message>
            <source>Output nodata value</source>
            <translation>قيمة nodata في المخرج</translation>
        </message>
        <message>
            <source>Rectified image</source>
            <translation>الصورة المصحَّحة هندسياً</translation>
        </message>
        <message>
            <source>OUTPUT must be a GeoTIFF file (.tif); got {0}.</source>
            <translation>يجب أن يكون OUTPUT ملف GeoTIFF (.tif)؛ القيمة المعطاة: {0}.</translation>
        </message>
        <message>
            <source>Rectify image with GCPs</source>
            <translation>تصحيح مرئية بنقاط الضبط الأرضي</translation>
        </message>
        <message>
            <source>Rectifies (warps) an image with ground control points through GDAL: a polynomial of order 1–3, a linear, Helmert, projective or thin-plate-spline transformation, or the one with the lowest check-point error. It writes the accuracy report by the paper's criteria and never modifies the input image.</source>
            <translation>يصحّح (يُطوّع) صورة بنقاط الضبط الأرضي عبر GDAL: بكثير حدود من الدرجة 1–3، أو بتحويل خطي أو هلمرت أو إسقاطي أو شرائح الصفائح الرقيقة، أو بالتحويل ذي أدنى خطأ على نقاط التحقق. يكتب تقرير الدقة وفق معايير الورقة ولا يعدّل صورة الإدخال أبدًا.</translation>
        </message>
        <message>
            <source>GDAL reprojects after the transformation.</source>
            <translation>يعيد GDAL الإسقاط بعد التحويل.</translation>
        </message>
        <message>
            <source>Nearest neighbour, as in the paper.</source>
            <translation>الجار الأقرب، كما في الورقة.</translation>
        </message>
        <message>
            <source>Default: the input's nodata, else 0.</source>
            <translation>الافتراضي: قيمة انعدام البيانات في الإدخال، وإلا 0.</translation>
        </message>
        <message>
            <source>GCP rectification report</source>
            <translation>تقرير التصحيح بنقاط الضبط الأرضي</translation>
        </message>
        <message>
            <source>Wrote {path}: {width} × {height} px at {resolution:.6g} {unit}/px, resampling {resampling}.</source>
            <translation>كُتب {path}: {width} × {height} بكسل بدقة {resolution:.6g} {unit}/بكسل، إعادة المعاينة {resampling}.</translation>
        </message>
    </context>
    <context>
        <name>SlopeGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (slope-based)</source>
            <translation>مرشح نقاط الأرض (على أساس الميل)</translation>
        </message>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,vosselman,slope,point cloud</source>
            <translation>ليدار,las,laz,أرض,مرشح,تصنيف,dtm,الأرض العارية,vosselman,الميل,سحابة النقاط</translation>
        </message>
        <message>
            <source>Radius r (m)</source>
            <translation>نصف القطر r (م)</translation>
        </message>
        <message>
            <source>Slope threshold θ (degrees)</source>
            <translation>عتبة الميل θ (درجة)</translation>
        </message>
        <message>
            <source>Height tolerance h (m)</source>
            <translation>سماحية الارتفاع h (م)</translation>
        </message>
        <message>
            <source>Keep existing noise classes (7, 18)</source>
            <translation>الإبقاء على أصناف الضوضاء الموجودة (7, 18)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط الأرض</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>النقاط المقروءة</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط الأرض (الصنف 2)</translation>
        </message>
        <message>
            <source>Non-ground points (class 1)</source>
            <translation>النقاط غير الأرضية (الصنف 1)</translation>
        </message>
        <message>
            <source>Low outliers (class 7)</source>
            <translation>القيم الشاذة المنخفضة (الصنف 7)</translation>
        </message>
        <message>
            <source>Filter speed (points/s)</source>
            <translation>سرعة الترشيح (نقطة/ث)</translation>
        </message>
        <message>
            <source>Slope filter: r = {} m, θ = {}°, h = {} m, {} returns, mode {}</source>
            <translation>مرشح الميل: ⁦r = {}⁩ م، ⁦θ = {}°⁩، ⁦h = {}⁩ م، الارتدادات: {}، النمط: {}</translation>
        </message>
        <message>
            <source>Classifies a LAS/LAZ point cloud into ground (class 2) and non-ground (class 1) with Vosselman's (2000) slope-based filter: a point is non-ground when a neighbour within the radius r lies more than d·tan θ + h below it. The filter is exact and fast (about a million points per second at r = 3 m); tune r and θ to your data with the slope filter threshold sweep.</source>
            <translation>يصنّف سحابة نقاط LAS/LAZ إلى أرض (الفئة 2) وغير أرض (الفئة 1) بمرشح الانحدار لـ Vosselman ‏(2000): تكون النقطة غير أرضية إذا وُجد جار ضمن نصف القطر r أدنى منها بأكثر من d·tan θ + h. المرشح دقيق وسريع (نحو مليون نقطة في الثانية عند r = 3 m)؛ اضبط r وθ على بياناتك بأداة مسح عتبات مرشح الانحدار.</translation>
        </message>
        <message>
            <source>Must exceed half the width of the largest building to remove; a larger radius costs more time.</source>
            <translation>يجب أن يتجاوز نصف عرض أكبر مبنى يُراد حذفه؛ ونصف القطر الأكبر يستغرق وقتًا أطول.</translation>
        </message>
        <message>
            <source>The steepest terrain kept, between 0 and 90°; the allowed rise at 3 m is 2.52 m at 40°, 2.90 m at 44° and 3.84 m at 52°.</source>
            <translation>أشد تضاريس تُحفظ، بين 0 و90°؛ الارتفاع المسموح على بُعد 3 m هو 2.52 m عند 40°، و2.90 m عند 44°، و3.84 m عند 52°.</translation>
        </message>
        <message>
            <source>Extra rise allowed for every pair, absorbs ranging noise; 0 is the published rule.</source>
            <translation>ارتفاع إضافي مسموح لكل زوج من النقاط يمتص ضجيج القياس؛ 0 هي القاعدة المنشورة.</translation>
        </message>
        <message>
            <source>Points already in class 7 or 18 keep their class and take no part.</source>
            <translation>النقاط المصنّفة مسبقًا في الفئة 7 أو 18 تحتفظ بفئتها ولا تشارك.</translation>
        </message>
        <message>
            <source>Every point with classes 2, 1 and 7; every other attribute is copied unchanged.</source>
            <translation>كل النقاط بالفئات 2 و1 و7؛ وتُنسخ كل الخصائص الأخرى دون تغيير.</translation>
        </message>
        <message>
            <source>Slope ground filter report</source>
            <translation>تقرير مرشح الأرض القائم على الانحدار</translation>
        </message>
    </context>
    <context>
        <name>SlopeThresholdSweepAlgorithm</name>
        <message>
            <source>Slope filter threshold sweep</source>
            <translation>مسح عتبات مرشح الميل</translation>
        </message>
        <message>
            <source>lidar,ground,filter,vosselman,slope,threshold,tuning,accuracy,type I,type II,kappa,isprs</source>
            <translation>ليدار,أرض,مرشح,vosselman,الميل,العتبة,المعايرة,الدقة,النوع الأول,النوع الثاني,كابا,isprs</translation>
        </message>
        <message>
            <source>Reference cloud (empty = the input's classification)</source>
            <translation>السحابة المرجعية (فارغ = تصنيف سحابة الإدخال نفسها)</translation>
        </message>
        <message>
            <source>Reference ground classes</source>
            <translation>أصناف الأرض في المرجع</translation>
        </message>
        <message>
            <source>Slope thresholds θ (degrees; list or start:stop:step)</source>
            <translation>عتبات الميل θ (درجات؛ قائمة أو بداية:نهاية:خطوة)</translation>
        </message>
        <message>
            <source>Radii r (m; list)</source>
            <translation>أنصاف الأقطار r (م؛ قائمة)</translation>
        </message>
        <message>
            <source>Height tolerances h (m; list)</source>
            <translation>سماحيات الارتفاع h (م؛ قائمة)</translation>
        </message>
        <message>
            <source>Best by</source>
            <translation>معيار الأفضلية</translation>
        </message>
        <message>
            <source>Lowest total error</source>
            <translation>أدنى خطأ كلي</translation>
        </message>
        <message>
            <source>Highest kappa</source>
            <translation>أعلى كابا</translation>
        </message>
        <message>
            <source>Lowest Type I error</source>
            <translation>أدنى خطأ من النوع الأول</translation>
        </message>
        <message>
            <source>Lowest Type II error</source>
            <translation>أدنى خطأ من النوع الثاني</translation>
        </message>
        <message>
            <source>Sweep table</source>
            <translation>جدول المسح</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>ملفات CSV (*.csv)</translation>
        </message>
        <message>
            <source>Classified with the best setting</source>
            <translation>السحابة المصنَّفة بأفضل إعداد</translation>
        </message>
        <message>
            <source>Best radius (m)</source>
            <translation>أفضل نصف قطر (م)</translation>
        </message>
        <message>
            <source>Best slope threshold (degrees)</source>
            <translation>أفضل عتبة ميل (درجة)</translation>
        </message>
        <message>
            <source>Best height tolerance (m)</source>
            <translation>أفضل سماحية ارتفاع (م)</translation>
        </message>
        <message>
            <source>Type I error at the best setting (%)</source>
            <translation>خطأ النوع الأول عند أفضل إعداد (%)</translation>
        </message>
        <message>
            <source>Type II error at the best setting (%)</source>
            <translation>خطأ النوع الثاني عند أفضل إعداد (%)</translation>
        </message>
        <message>
            <source>Total error at the best setting (%)</source>
            <translation>الخطأ الكلي عند أفضل إعداد (%)</translation>
        </message>
        <message>
            <source>Kappa at the best setting (%)</source>
            <translation>كابا عند أفضل إعداد (%)</translation>
        </message>
        <message>
            <source>Settings evaluated</source>
            <translation>عدد الإعدادات المقيَّمة</translation>
        </message>
        <message>
            <source>Best setting</source>
            <translation>أفضل إعداد</translation>
        </message>
        <message>
            <source>Sweeping {} thresholds × {} radii × {} tolerances</source>
            <translation>مسح {} عتبات × {} أنصاف أقطار × {} سماحيات</translation>
        </message>
        <message>
            <source>Best ({}): {} — total {:.2f} %</source>
            <translation>الأفضل ({}): {} — الخطأ الكلي {:.2f} %</translation>
        </message>
        <message>
            <source>Runs the slope-based ground filter for every combination of slope thresholds θ, radii r and height tolerances h, and measures each against reference labels: Type I and Type II errors, total error and Cohen's kappa (Sithole &amp;amp; Vosselman 2004). It then picks the best setting, at the cost of one neighbourhood pass per radius and tolerance.</source>
            <translation>يشغّل مرشح الأرض القائم على الانحدار لكل توليفة من عتبات الانحدار θ وأنصاف الأقطار r وسماحيات الارتفاع h، ويقيس كلًّا منها مقابل التصنيفات المرجعية: خطأ النوع الأول والثاني، والخطأ الكلي، ومعامل كابا لكوهين (Sithole &amp;amp; Vosselman 2004). ثم يختار أفضل إعداد، بكلفة مرور جواري واحد لكل نصف قطر وسماحية.</translation>
        </message>
        <message>
            <source>Its classification is never used to filter.</source>
            <translation>لا يُستخدم تصنيفها في الترشيح أبدًا.</translation>
        </message>
        <message>
            <source>A labelled copy of the same points in the same order, e.g. the ISPRS reference samples.</source>
            <translation>نسخة مصنّفة من النقاط نفسها بالترتيب نفسه، مثل عيّنات ISPRS المرجعية.</translation>
        </message>
        <message>
            <source>Every other class counts as an object.</source>
            <translation>تُعدّ كل فئة أخرى جسمًا.</translation>
        </message>
        <message>
            <source>A list such as 40, 44, 48 or start:stop:step.</source>
            <translation>قائمة مثل 40, 44, 48 أو start:stop:step.</translation>
        </message>
        <message>
            <source>Each value is one neighbourhood pass.</source>
            <translation>كل قيمة تعني مرور جوار واحد.</translation>
        </message>
        <message>
            <source>One row per setting with the cross matrix and the errors in percent.</source>
            <translation>صف لكل إعداد يضم المصفوفة المتقاطعة والأخطاء بالنسبة المئوية.</translation>
        </message>
        <message>
            <source>Slope threshold sweep report</source>
            <translation>تقرير مسح عتبات مرشح الانحدار</translation>
        </message>
    </context>
    <context>
        <name>TinDtmAlgorithm</name>
        <message>
            <source>DTM by TIN (Delaunay linear interpolation)</source>
            <translation>نموذج تضاريس رقمي بـ TIN (استيفاء خطي ديلوني)</translation>
        </message>
        <message>
            <source>Terrain raster from the planes of the ground points' Delaunay triangles, gaps left empty.</source>
            <translation>شبكة تضاريس من مستويات مثلثات ديلوني لنقاط الأرض، مع ترك الفجوات فارغة.</translation>
        </message>
        <message>
            <source>dtm,dem,tin,delaunay,triangulation,linear,gdal_grid,blast2dem,lidar,ground,raster</source>
            <translation>نموذج تضاريس,dem,tin,ديلوني,تثليث,خطي,gdal_grid,blast2dem,ليدار,أرض,شبكة</translation>
        </message>
        <message>
            <source>Maximum triangle edge (m, 0 = auto)</source>
            <translation>أقصى طول لضلع المثلث (م، 0 = تلقائي)</translation>
        </message>
        <message>
            <source>Fill gaps (keep long triangles)</source>
            <translation>ملء الفجوات (إبقاء المثلثات الطويلة)</translation>
        </message>
        <message>
            <source>TIN DTM</source>
            <translation>نموذج تضاريس TIN</translation>
        </message>
        <message>
            <source>TIN DTM report</source>
            <translation>تقرير نموذج التضاريس TIN</translation>
        </message>
        <message>
            <source>Triangulates the ground points of a LAS/LAZ file (Delaunay) and gives every cell centre the height of the plane of its triangle, as &lt;code&gt;gdal_grid -a linear&lt;/code&gt; does. Triangles with an edge longer than the maximum are dropped, so gaps under buildings or water stay nodata unless you fill them.</source>
            <translation>يثلّث نقاط الأرض في ملف LAS/LAZ (ديلوني) ويعطي مركز كل خلية ارتفاع مستوى مثلثها، كما يفعل &lt;code&gt;gdal_grid -a linear&lt;/code&gt;. تُحذف المثلثات التي يتجاوز أحد أضلاعها الحد الأقصى، فتبقى الفجوات تحت المباني أو المياه بلا بيانات ما لم تملأها.</translation>
        </message>
        <message>
            <source>0 = ten mean point spacings (at least four cells); cells in longer triangles are nodata.</source>
            <translation>0 = عشرة أضعاف متوسط التباعد بين النقاط (أربع خلايا على الأقل)؛ الخلايا الواقعة في مثلثات أطول تُترك بلا بيانات.</translation>
        </message>
        <message>
            <source>Keeps every triangle, bridging gaps inside the convex hull with flat facets.</source>
            <translation>يُبقي كل المثلثات، فيجسر الفجوات داخل الغلاف المحدّب بأوجه مستوية.</translation>
        </message>
        <message>
            <source>Points triangulated</source>
            <translation>النقاط المثلّثة</translation>
        </message>
        <message>
            <source>Triangles</source>
            <translation>المثلثات</translation>
        </message>
        <message>
            <source>Cells with a value</source>
            <translation>خلايا ذات قيمة</translation>
        </message>
        <message>
            <source>Nodata cells</source>
            <translation>خلايا بلا بيانات</translation>
        </message>
    </context>
    <context>
        <name>TransformationParams</name>
        <message>
            <source>CRS of the GCP map coordinates (if the file does not say)</source>
            <translation>نظام الإحداثيات للإحداثيات الخرائطية لنقاط الضبط (إن لم يحدده الملف)</translation>
        </message>
        <message>
            <source>Transformation</source>
            <translation>التحويل</translation>
        </message>
        <message>
            <source>polynomial of the order set below</source>
            <translation>كثير حدود بالدرجة المحدّدة أدناه</translation>
        </message>
        <message>
            <source>polynomial order 1 (affine)</source>
            <translation>كثيرة حدود من الدرجة 1 (تآلفي)</translation>
        </message>
        <message>
            <source>polynomial order 2</source>
            <translation>كثيرة حدود من الدرجة 2</translation>
        </message>
        <message>
            <source>polynomial order 3</source>
            <translation>كثيرة حدود من الدرجة 3</translation>
        </message>
        <message>
            <source>linear (shift and scale per axis)</source>
            <translation>خطي (إزاحة ومقياس لكل محور)</translation>
        </message>
        <message>
            <source>Helmert (shift, scale, rotation)</source>
            <translation>هلمرت (إزاحة، مقياس، دوران)</translation>
        </message>
        <message>
            <source>projective (homography)</source>
            <translation>إسقاطي (تحويل متجانس)</translation>
        </message>
        <message>
            <source>thin-plate spline</source>
            <translation>شريحة الصفيحة الرقيقة</translation>
        </message>
        <message>
            <source>recommended (lowest check-point / leave-one-out error)</source>
            <translation>الموصى به (أصغر خطأ على نقاط التحقق / ترك واحدة خارجاً)</translation>
        </message>
        <message>
            <source>Polynomial order (1–3)</source>
            <translation>درجة متعدد الحدود (1–3)</translation>
        </message>
        <message>
            <source>Refine GCPs: drop the worst while over the tolerance</source>
            <translation>تنقيح النقاط: حذف الأسوأ ما دام فوق التسامح</translation>
        </message>
    </context>
    <context>
        <name>_GcpBase</name>
        <message>
            <source>Image (raster) to rectify</source>
            <translation>الصورة (راستر) المراد تصحيحها</translation>
        </message>
        <message>
            <source>Image (raster) the GCPs were measured on</source>
            <translation>الصورة (راستر) التي قيست عليها نقاط الضبط</translation>
        </message>
        <message>
            <source>GCP file (.points or CSV)</source>
            <translation>ملف نقاط الضبط الأرضي (.points أو CSV)</translation>
        </message>
        <message>
            <source>GCP files (*.points *.csv *.txt);;All files (*.*)</source>
            <translation>ملفات نقاط الضبط (*.points *.csv *.txt);;جميع الملفات (*.*)</translation>
        </message>
        <message>
            <source>…or GCP point layer</source>
            <translation>…أو طبقة نقطية لنقاط الضبط</translation>
        </message>
        <message>
            <source>Layer field: image column</source>
            <translation>حقل الطبقة: عمود الصورة</translation>
        </message>
        <message>
            <source>Layer field: image row</source>
            <translation>حقل الطبقة: صف الصورة</translation>
        </message>
        <message>
            <source>Layer field: point id</source>
            <translation>حقل الطبقة: معرِّف النقطة</translation>
        </message>
        <message>
            <source>Layer field: enabled (1/0)</source>
            <translation>حقل الطبقة: مفعَّلة (1/0)</translation>
        </message>
        <message>
            <source>Layer field: role (gcp/check)</source>
            <translation>حقل الطبقة: الدور (gcp/check)</translation>
        </message>
        <message>
            <source>Layer field: weight (&gt; 0)</source>
            <translation>حقل الطبقة: الوزن (&gt; 0)</translation>
        </message>
        <message>
            <source>Image coordinates refer to</source>
            <translation>إحداثيات الصورة تشير إلى</translation>
        </message>
        <message>
            <source>pixel corners: (0,0) = top-left corner of the image (GDAL/QGIS)</source>
            <translation>أركان البكسلات: (0,0) = الركن العلوي الأيسر للصورة (GDAL/QGIS)</translation>
        </message>
        <message>
            <source>pixel centres: integer = centre of a pixel (0-based indices)</source>
            <translation>مراكز البكسلات: العدد الصحيح = مركز بكسل (فهارس تبدأ من 0)</translation>
        </message>
        <message>
            <source>Ground resolution GR (map units/pixel) [default: from the GCPs]</source>
            <translation>الدقة الأرضية GR (وحدة خريطة/بكسل) [الافتراضي: من نقاط الضبط]</translation>
        </message>
        <message>
            <source>INPUT: no image given or it cannot be opened; give a raster file.</source>
            <translation>INPUT: لم تُحدَّد صورة أو تعذّر فتحها؛ حدِّد ملف راستر.</translation>
        </message>
        <message>
            <source>INPUT: {0} is not a local raster file; save the image to a file first.</source>
            <translation>INPUT: {0} ليس ملف راستر محلياً؛ احفظ الصورة في ملف أولاً.</translation>
        </message>
        <message>
            <source>Give either GCP_FILE or GCP_LAYER, not both.</source>
            <translation>حدِّد GCP_FILE أو GCP_LAYER، لا الاثنين معاً.</translation>
        </message>
        <message>
            <source>No GCPs: give a GCP file (GCP_FILE, .points or CSV) or a point layer (GCP_LAYER with COL_FIELD and ROW_FIELD); no &lt;image&gt;.points file was found next to the image either.</source>
            <translation>لا توجد نقاط ضبط: حدِّد ملف نقاط ضبط (GCP_FILE، بالامتداد .points أو CSV) أو طبقة نقطية (GCP_LAYER مع COL_FIELD وROW_FIELD)؛ ولم يُعثر كذلك على ملف &lt;image&gt;.points بجوار الصورة.</translation>
        </message>
        <message>
            <source>GCP_LAYER needs COL_FIELD and ROW_FIELD: the fields holding the image column and row of each point.</source>
            <translation>تتطلب GCP_LAYER الحقلين COL_FIELD وROW_FIELD: الحقلين اللذين يحويان عمود الصورة وصفّها لكل نقطة.</translation>
        </message>
        <message>
            <source>GCP layer feature {0} has no geometry.</source>
            <translation>العنصر {0} في طبقة نقاط الضبط ليست له هندسة.</translation>
        </message>
        <message>
            <source>The GCP map coordinates have no CRS: the file has no '#CRS:' line and GCP_CRS is not set. Set GCP_CRS (e.g. EPSG:22780) and run again.</source>
            <translation>الإحداثيات الخرائطية لنقاط الضبط بلا نظام إحداثيات: لا يحوي الملف السطر '#CRS:' ولم يُضبط GCP_CRS. اضبط GCP_CRS (مثلاً EPSG:22780) وأعد التشغيل.</translation>
        </message>
        <message>
            <source>The GCP CRS is geographic (degrees): the accuracy criteria need map units of length. Set TARGET_CRS (or GCP_CRS) to a projected CRS, e.g. the UTM zone of the image.</source>
            <translation>نظام إحداثيات نقاط الضبط جغرافي (بالدرجات): تتطلب معايير الدقة وحدات خريطة طولية. اضبط TARGET_CRS (أو GCP_CRS) على نظام إحداثيات مُسقَط، مثل نطاق UTM الذي تقع فيه الصورة.</translation>
        </message>
        <message>
            <source>Refinement tolerance (map units) [default: C5 limit 5·GR]</source>
            <translation>تسامح التنقيح (وحدات الخريطة) [الافتراضي: حدّ C5 أي 5·GR]</translation>
        </message>
        <message>
            <source>Minimum GCPs kept by the refinement [default: minimum + 2]</source>
            <translation>أدنى عدد نقاط يبقيه التنقيح [الافتراضي: الحدّ الأدنى + 2]</translation>
        </message>
        <message>
            <source>A QGIS Georeferencer .points file or a CSV table with id, col, row, X, Y and optional enabled, role (gcp or check) and weight. Give the file or a point layer.</source>
            <translation>ملف ‎.points‎ من المُرجِع الجغرافي في QGIS أو جدول CSV بالأعمدة id وcol وrow وX وY، واختياريًا enabled وrole ‏(gcp أو check) وweight. أدخل الملف أو طبقة نقطية.</translation>
        </message>
        <message>
            <source>Its geometry gives the map coordinates; the fields below give the image coordinates.</source>
            <translation>تعطي هندستها إحداثيات الخريطة؛ وتعطي الحقول التالية إحداثيات الصورة.</translation>
        </message>
        <message>
            <source>Needed when the file does not state its CRS.</source>
            <translation>مطلوب عندما لا يذكر الملف نظام إحداثياته.</translation>
        </message>
        <message>
            <source>The last choice picks the transformation with the lowest check-point or leave-one-out error.</source>
            <translation>الخيار الأخير يختار التحويل ذا أدنى خطأ على نقاط التحقق أو بالاستبعاد الفردي.</translation>
        </message>
        <message>
            <source>Drops the worst point while a residual exceeds the tolerance, keeping at least the minimum number of GCPs.</source>
            <translation>يحذف أسوأ نقطة ما دام أحد البواقي يتجاوز السماحية، مع الإبقاء على الحد الأدنى من نقاط الضبط.</translation>
        </message>
        <message>
            <source>Sets the map scale S = 20000·GR and the tolerance band 4·GR to 6·GR of the criteria (Tishreen Univ. J. Eng. Sci. 38(2), 2016).</source>
            <translation>يحدّد مقياس الخريطة S = 20000·GR ونطاق السماحية من 4·GR إلى 6·GR في المعايير (مجلة جامعة تشرين للعلوم الهندسية 38(2)، 2016).</translation>
        </message>
        <message>
            <source>Transformation used</source>
            <translation>التحويل المستخدم</translation>
        </message>
        <message>
            <source>Recommended transformation</source>
            <translation>التحويل المُوصى به</translation>
        </message>
        <message>
            <source>A run that gives the polynomial order but no transformation (the command line of earlier versions) uses a polynomial of that order.</source>
            <translation>التشغيل الذي يحدّد رتبة كثيرة الحدود دون تحويل (سطر الأوامر في الإصدارات السابقة) يستخدم كثيرة حدود من تلك الرتبة.</translation>
        </message>
        <message>
            <source>{kind}: fit RMS_T = {fit:.4f} {unit}, {basis} RMS_T = {honest:.4f} {unit} (n = {n}); verdict: {verdict}.</source>
            <translation>{kind}: RMS_T للملاءمة = {fit:.4f} {unit}، RMS_T ({basis}) = {honest:.4f} {unit} (⁦n = {n}⁩)؛ الحكم: {verdict}.</translation>
        </message>
        <message>
            <source>Recommended transformation: {kind}, the fewest parameters among those within 10 % of the best {basis} RMS_T ({ranking} {unit}).</source>
            <translation>التحويل الموصى به: {kind}، الأقل معاملاتٍ بين التحويلات التي يقع RMS_T لها ({basis}) ضمن 10 % من الأفضل ({ranking} {unit}).</translation>
        </message>
        <message>
            <source>No transformation has enough GCPs to be judged on independent residuals; add GCPs.</source>
            <translation>لا يملك أيّ تحويل نقاط ضبط كافية للحكم عليه ببواقٍ مستقلة؛ أضف نقاط ضبط.</translation>
        </message>
        <message>
            <source>Refinement dropped GCP {id} (residual {residual:.4f} {unit}; {left} left).</source>
            <translation>أسقط التنقيح نقطة الضبط {id} (الباقي {residual:.4f} {unit}؛ بقي {left}).</translation>
        </message>
    </context>
    <context>
        <name>_GridAlgorithm</name>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>حجم الخلية (م)</translation>
        </message>
        <message>
            <source>Extent</source>
            <translation>النطاق</translation>
        </message>
        <message>
            <source>CRS (overrides the LAS file's CRS)</source>
            <translation>نظام الإحداثيات (يتقدّم على نظام إحداثيات ملف LAS)</translation>
        </message>
        <message>
            <source>Maximum distance to data (m, 0 = auto)</source>
            <translation>أقصى مسافة إلى البيانات (م، 0 = تلقائي)</translation>
        </message>
        <message>
            <source>Fill data gaps (interpolate far from data)</source>
            <translation>ملء فجوات البيانات (الاستيفاء بعيداً عن البيانات)</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>سحابة النقاط لا تحوي سجل نظام إحداثيات ولم يُحدَّد نظام إحداثيات؛ اضبط المعامل CRS (مثلاً EPSG:32632). لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>Reading points of class(es) {} from {}</source>
            <translation>جارٍ قراءة نقاط الصنف (الأصناف) {} من {}</translation>
        </message>
        <message>
            <source>{} of {} points selected</source>
            <translation>اختيرت {} نقطة من أصل {}</translation>
        </message>
        <message>
            <source>Classes used (none = all)</source>
            <translation>الفئات المستخدمة (بلا اختيار = الكل)</translation>
        </message>
        <message>
            <source>Default: the extent of the selected points, snapped outward to whole cells so that tiles line up.</source>
            <translation>الافتراضي: امتداد النقاط المختارة، مُوسَّعًا إلى خلايا كاملة كي تتطابق حدود البلاطات.</translation>
        </message>
        <message>
            <source>Needed when the LAS file has no CRS.</source>
            <translation>مطلوب عندما لا يحمل ملف LAS نظامَ إحداثيات مرجعيًا.</translation>
        </message>
        <message>
            <source>0 = five mean point spacings (at least two cells); cells farther from any point are nodata.</source>
            <translation>0 = خمسة أضعاف متوسط التباعد بين النقاط (خليتان على الأقل)؛ الخلايا الأبعد عن أي نقطة تُترك بلا بيانات.</translation>
        </message>
        <message>
            <source>Interpolates every cell, ignoring the maximum distance.</source>
            <translation>يستكمل كل الخلايا متجاهلًا المسافة القصوى.</translation>
        </message>
        <message>
            <source>GeoTIFF (float32, nodata −9999) in the cloud's CRS.</source>
            <translation>ملف GeoTIFF (float32، قيمة انعدام البيانات ‎−9999‎) بنظام إحداثيات السحابة.</translation>
        </message>
        <message>
            <source>all</source>
            <translation>الكل</translation>
        </message>
    </context>
    <context>
        <name>_GroundCommon</name>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,point cloud</source>
            <translation>ليدار,las,laz,أرض,مرشح,تصنيف,نموذج تضاريس رقمي,أرض عارية,سحابة نقاط</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Keep existing noise classes (7, 18)</source>
            <translation>الإبقاء على أصناف الضوضاء الموجودة (7, 18)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط الأرض</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>النقاط المقروءة</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط الأرض (الصنف 2)</translation>
        </message>
        <message>
            <source>Non-ground points (class 1)</source>
            <translation>النقاط غير الأرضية (الصنف 1)</translation>
        </message>
        <message>
            <source>Low outliers (class 7)</source>
            <translation>القيم الشاذة المنخفضة (الصنف 7)</translation>
        </message>
        <message>
            <source>Filter speed (points/s)</source>
            <translation>سرعة الترشيح (نقطة/ث)</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>تقرير مرشح الأرض</translation>
        </message>
        <message>
            <source>A .las or .laz file in a projected CRS (metres).</source>
            <translation>ملف .las أو .laz في نظام إحداثيات مُسقط (بالأمتار).</translation>
        </message>
        <message>
            <source>Every point with class 2 ground, 1 other or 7 low noise; every other attribute, VLR and the CRS copied unchanged.</source>
            <translation>كل نقطة بالفئة 2 أرض أو 1 أخرى أو 7 ضوضاء منخفضة؛ وتُنسخ كل الخصائص الأخرى وسجلات VLR ونظام الإحداثيات دون تغيير.</translation>
        </message>
        <message>
            <source>Only the ground points.</source>
            <translation>النقاط الأرضية فقط.</translation>
        </message>
        <message>
            <source>Points already classified 7 or 18 keep their class and take no part.</source>
            <translation>النقاط المصنفة مسبقًا 7 أو 18 تحتفظ بفئتها ولا تشارك.</translation>
        </message>
        <message>
            <source>Points far below their neighbours (multipath) get class 7 and take no part: one stray low point would reject every ground point around it.</source>
            <translation>النقاط الواقعة أدنى بكثير من جيرانها (تعدد المسارات) تأخذ الفئة 7 ولا تشارك: فنقطة منخفضة شاردة واحدة كانت سترفض كل نقاط الأرض حولها.</translation>
        </message>
        <message>
            <source>Side of the cells searched for lower neighbours.</source>
            <translation>ضلع الخلايا التي يُبحث فيها عن جيران أدنى.</translation>
        </message>
        <message>
            <source>A point this far below the points around it is a low outlier.</source>
            <translation>النقطة التي تنخفض بهذا القدر عن النقاط المحيطة بها قيمة شاذة منخفضة.</translation>
        </message>
    </context>
    <context>
        <name>_SlopeCommon</name>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Returns filtered</source>
            <translation>الارتدادات المرشحة</translation>
        </message>
        <message>
            <source>All returns</source>
            <translation>جميع الارتدادات</translation>
        </message>
        <message>
            <source>Last returns only</source>
            <translation>الارتدادات الأخيرة فقط</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>النمط</translation>
        </message>
        <message>
            <source>Exact (Vosselman 2000)</source>
            <translation>دقيق (Vosselman 2000)</translation>
        </message>
        <message>
            <source>Terrain-adaptive (toolbox extension)</source>
            <translation>متكيِّف مع التضاريس (إضافة من صندوق الأدوات)</translation>
        </message>
        <message>
            <source>Adaptive mode: trend cell (m)</source>
            <translation>النمط المتكيِّف: خلية الاتجاه العام (م)</translation>
        </message>
        <message>
            <source>Adaptive mode: trend window, &gt; largest building (m)</source>
            <translation>النمط المتكيِّف: نافذة الاتجاه العام، &gt; أكبر مبنى (م)</translation>
        </message>
        <message>
            <source>TREND_CELL and TREND_WINDOW must be &gt; 0 metres in adaptive mode (e.g. 10 and 60).</source>
            <translation>يجب أن تكون قيمتا TREND_CELL وTREND_WINDOW &gt; 0 م في النمط المتكيِّف (مثلاً 10 و60).</translation>
        </message>
        <message>
            <source>NOISE_RADIUS and NOISE_THRESHOLD must be &gt; 0 metres (e.g. 5 and 1), or switch the NOISE pre-filter off.</source>
            <translation>يجب أن تكون قيمتا NOISE_RADIUS وNOISE_THRESHOLD &gt; 0 م (مثلاً 5 و1)، أو أوقف الترشيح المسبق NOISE.</translation>
        </message>
        <message>
            <source>All returns: every return is classified and is a neighbour (the forest study). Last returns only: first and intermediate returns get class 1; files without return numbers count every point as a last return.</source>
            <translation>كل الانعكاسات: يُصنَّف كل انعكاس ويُعدّ جارًا (دراسة الغابة). الانعكاسات الأخيرة فقط: تأخذ الانعكاسات الأولى والوسيطة الفئة 1، والملفات التي لا تحمل أرقام انعكاس تَعدّ كل نقطة انعكاسًا أخيرًا.</translation>
        </message>
        <message>
            <source>Points far below their neighbours (multipath) get class 7 and take no part: one stray low point would reject every ground point around it.</source>
            <translation>النقاط الواقعة أدنى بكثير من جيرانها (تعدد المسارات) تأخذ الفئة 7 ولا تشارك: فنقطة منخفضة شاردة واحدة كانت سترفض كل نقاط الأرض حولها.</translation>
        </message>
        <message>
            <source>Terrain-adaptive (this toolbox's extension) applies the rule to heights above a smooth low terrain trend, so natural slopes steeper than θ are kept (ISPRS samp11: total error 21.0 % → 16.4 %); use a lower θ, about 30–35°, in this mode.</source>
            <translation>النمط المتكيّف مع التضاريس (امتداد من هذه الأداة) يطبّق القاعدة على الارتفاعات فوق اتجاه تضاريسي منخفض وأملس، فتُحفظ المنحدرات الطبيعية الأشد من θ ‏(ISPRS samp11: الخطأ الكلي 21.0 % ← 16.4 %)؛ استخدم θ أصغر، نحو 30–35°، في هذا النمط.</translation>
        </message>
    </context>
</TS>
