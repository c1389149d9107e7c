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
            <source>&lt;p&gt;Extracts buildings from a ground-classified LAS/LAZ cloud: points more than the minimum height above a TIN of the ground points are fitted with local planes; neighbours whose normals agree within the maximum angle grow into roof patches; patches of at least the minimum patch area become footprints with height (top of roof − ground at the outline), area, volume, storeys (height / 3 m) and roof type (flat / pitched). Trees are rejected because their points are not planar.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground_filtered.laz MIN_HEIGHT=2 MAX_ANGLE=20 OUTPUT=buildings.gpkg OUTPUT_CLOUD=classified.laz.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las/.laz with ground in class 2 (run a ground filter first), projected CRS in metres.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground classes&lt;/b&gt; (GROUND_CLASSES, default &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum height&lt;/b&gt; (MIN_HEIGHT, m, default 2; the spec gives 1.5–2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Maximum normal angle&lt;/b&gt; (MAX_ANGLE, degrees, default 20).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum roof patch area&lt;/b&gt; (MIN_PATCH_AREA, m², default 15).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum building area&lt;/b&gt; (MIN_AREA, m², default 15).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 0.5): footprint raster.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Footprints&lt;/b&gt; (OUTPUT, GeoPackage polygons): id, height_m, area_m2, volume_m3, storeys, roof_type, ground_z, roof_z.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classified cloud&lt;/b&gt; (OUTPUT_CLOUD, optional LAS/LAZ): the input with roof points set to class 6, every other attribute kept.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: N_BUILDINGS, TOTAL_AREA (m²), TOTAL_VOLUME (m³).&lt;/p&gt;</source>
            <translation>&lt;p&gt;يستخرج المباني من سحابة LAS/LAZ مصنّفة الأرض: تُطابَق النقاط التي تعلو نموذج TIN لنقاط الأرض بأكثر من الارتفاع الأدنى بمستويات محلية؛ وتنمو النقاط المتجاورة التي تتفق نواظمها ضمن الزاوية القصوى إلى رقع أسطح؛ والرقع التي تبلغ المساحة الدنيا تصبح مساقط مع الارتفاع (أعلى السطح − الأرض عند المحيط) والمساحة والحجم والطوابق (الارتفاع / 3 م) ونوع السطح (مسطّح / مائل). تُستبعد الأشجار لأن نقاطها غير مستوية.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground_filtered.laz MIN_HEIGHT=2 MAX_ANGLE=20 OUTPUT=buildings.gpkg OUTPUT_CLOUD=classified.laz.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف ‎.las/.laz فيه الأرض في الصنف 2 (شغّل مرشّح أرض أولاً)، بنظام إسقاط مستوٍ بالأمتار.&lt;/li&gt;&lt;li&gt;&lt;b&gt;أصناف الأرض&lt;/b&gt; (GROUND_CLASSES، الافتراضي &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الارتفاع الأدنى&lt;/b&gt; (MIN_HEIGHT، م، الافتراضي 2؛ تعطي المواصفة 1.5–2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أقصى زاوية للنواظم&lt;/b&gt; (MAX_ANGLE، درجة، الافتراضي 20).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أدنى مساحة لرقعة السطح&lt;/b&gt; (MIN_PATCH_AREA، م²، الافتراضي 15).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أدنى مساحة للمبنى&lt;/b&gt; (MIN_AREA، م²، الافتراضي 15).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم الخلية&lt;/b&gt; (CELL_SIZE، م، الافتراضي 0.5): شبكة المساقط.&lt;/li&gt;&lt;li&gt;&lt;b&gt;المساقط&lt;/b&gt; (OUTPUT، مضلعات GeoPackage): id وheight_m وarea_m2 وvolume_m3 وstoreys وroof_type وground_z وroof_z.&lt;/li&gt;&lt;li&gt;&lt;b&gt;السحابة المصنّفة&lt;/b&gt; (OUTPUT_CLOUD، LAS/LAZ اختياري): المدخل مع وضع نقاط الأسطح في الصنف 6 والحفاظ على كل السمات الأخرى.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;الأعداد الناتجة: N_BUILDINGS وTOTAL_AREA (م²) وTOTAL_VOLUME (م³).&lt;/p&gt;</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>&lt;p&gt;Classifies ground and builds a DTM for every tile of a LiDAR project, each tile read with a buffer of points from its neighbours so that results have no seams at tile edges; tiles run in parallel on Dask, locally or on a cluster. Example: INPUT = a folder of 1 km LAZ tiles, BUFFER = 100 m, CELL_SIZE = 1 m gives classified tiles, one DTM GeoTIFF per tile and a VRT mosaic.&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Tiles&lt;/b&gt; (INPUT): a folder of .las/.laz files, a .vpc virtual point cloud, or files separated by ';'. All tiles must share one CRS.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground filter&lt;/b&gt; (GROUND_FILTER, default the recommended one): 0 keeps the classes already in the files.&lt;/li&gt;&lt;li&gt;&lt;b&gt;DTM method&lt;/b&gt; (DTM_METHOD, default IDW) and &lt;b&gt;cell size&lt;/b&gt; (CELL_SIZE, m, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Buffer&lt;/b&gt; (BUFFER, m, default 100): must exceed the filter's reach (LSQ tile size × 2, slope radius) and the DTM search distance.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Workers&lt;/b&gt; (WORKERS, default 0 = one per core) and &lt;b&gt;Dask scheduler&lt;/b&gt; (SCHEDULER, e.g. tcp://host:8786; empty = a local cluster).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output folder&lt;/b&gt; (OUTPUT_FOLDER; must not hold the input tiles): &amp;lt;tile&amp;gt;_classified, &amp;lt;tile&amp;gt;_dtm.tif, dtm.vrt, optionally one Cloud-Optimized GeoTIFF (COG), and the HTML report (OUTPUT_HTML) with a map of the tiles by status and time and points per second per worker. A rerun skips finished tiles; cancel keeps finished tiles.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;يصنّف نقاط الأرض وينشئ نموذج تضاريس رقمياً لكل بلاطة في مشروع ليدار، وتُقرأ كل بلاطة مع هامش من نقاط جيرانها كي لا تظهر فواصل عند حواف البلاطات؛ وتُعالَج البلاطات بالتوازي على Dask محلياً أو على عنقود حواسيب. مثال: INPUT = مجلد بلاطات LAZ بطول 1 كم، BUFFER = 100 م، CELL_SIZE = 1 م ينتج بلاطات مصنّفة وملف GeoTIFF للتضاريس لكل بلاطة وفسيفساء VRT.&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;البلاطات&lt;/b&gt; (INPUT): مجلد ملفات ‎.las/.laz أو سحابة نقاط افتراضية ‎.vpc أو ملفات تفصل بينها ';'. يجب أن تشترك كل البلاطات في نظام إحداثيات واحد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;مرشح الأرض&lt;/b&gt; (GROUND_FILTER، الافتراضي هو الموصى به): 0 يُبقي الأصناف الموجودة في الملفات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;طريقة نموذج التضاريس&lt;/b&gt; (DTM_METHOD، الافتراضي IDW) و&lt;b&gt;حجم الخلية&lt;/b&gt; (CELL_SIZE، م، الافتراضي 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الهامش&lt;/b&gt; (BUFFER، م، الافتراضي 100): يجب أن يتجاوز مدى المرشح (ضعف حجم بلاطة المربعات الصغرى، نصف قطر الميل) ومسافة البحث في النموذج.&lt;/li&gt;&lt;li&gt;&lt;b&gt;العمليات العاملة&lt;/b&gt; (WORKERS، الافتراضي 0 = واحدة لكل نواة) و&lt;b&gt;مجدول Dask&lt;/b&gt; (SCHEDULER، مثل tcp://host:8786؛ فارغ = عنقود محلي).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مجلد النواتج&lt;/b&gt; (OUTPUT_FOLDER؛ يجب ألا يحوي بلاطات الإدخال): &amp;lt;tile&amp;gt;_classified و&amp;lt;tile&amp;gt;_dtm.tif وdtm.vrt واختيارياً ملف GeoTIFF واحد محسَّن للسحابة (COG) وتقرير HTML ‏(OUTPUT_HTML) فيه خريطة البلاطات حسب الحالة والزمن وعدد النقاط في الثانية لكل عامل. إعادة التشغيل تتخطى البلاطات المنتهية؛ والإلغاء يُبقي البلاطات المنتهية.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Tiles: folder, .vpc or files separated by ';'</source>
            <translation>البلاطات: مجلد أو ‎.vpc أو ملفات تفصل بينها ';'</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>&lt;p&gt;Digital surface model from a LAS/LAZ file: every cell takes the highest return falling in it (first returns only as an option, the usual canopy surface). With a DTM, also the normalised DSM (nDSM; canopy height model in forests) = DSM − DTM on the DTM's grid. Points are read in chunks, so large files fit in memory.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=cloud.laz CELL_SIZE=1 FIRST_RETURNS=true DTM=dtm.tif OUTPUT=dsm.tif OUTPUT_NDSM=chm.tif.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las/.laz.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classes used&lt;/b&gt; (CLASSES, default empty = all classes).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Excluded classes&lt;/b&gt; (EXCLUDE_CLASSES, default &lt;code&gt;7,18&lt;/code&gt;: low and high noise).&lt;/li&gt;&lt;li&gt;&lt;b&gt;First returns only&lt;/b&gt; (FIRST_RETURNS, default no).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 1), &lt;b&gt;Extent&lt;/b&gt; (EXTENT), &lt;b&gt;CRS&lt;/b&gt; (CRS): as for the DTM tools; ignored when a DTM is given (its grid and CRS are used so that DSM and DTM align cell for cell).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Fill distance&lt;/b&gt; (FILL_DISTANCE, m, default 0): empty cells take the value of the nearest non-empty cell within this distance; 0 = leave them nodata.&lt;/li&gt;&lt;li&gt;&lt;b&gt;DTM&lt;/b&gt; (DTM, optional raster): needed for the nDSM.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Clamp negative heights to 0&lt;/b&gt; (CLAMP_NEGATIVE, default yes).&lt;/li&gt;&lt;li&gt;&lt;b&gt;DSM&lt;/b&gt; (OUTPUT) and &lt;b&gt;nDSM&lt;/b&gt; (OUTPUT_NDSM, optional, needs DTM): GeoTIFF, nodata −9999.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional).&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;نموذج السطح الرقمي من ملف LAS/LAZ: تأخذ كل خلية أعلى ارتداد يقع فيها (مع خيار الاقتصار على الارتدادات الأولى، وهو سطح الغطاء النباتي المعتاد). ومع نموذج ارتفاعات رقمي للأرض (DTM) يُحسب أيضاً نموذج السطح المُطبَّع (nDSM؛ نموذج ارتفاع الغطاء النباتي في الغابات) = DSM − DTM على شبكة DTM. تُقرأ النقاط على دفعات، لذا تتسع الذاكرة للملفات الكبيرة.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=cloud.laz CELL_SIZE=1 FIRST_RETURNS=true DTM=dtm.tif OUTPUT=dsm.tif OUTPUT_NDSM=chm.tif.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف .las/.laz.&lt;/li&gt;&lt;li&gt;&lt;b&gt;الأصناف المستخدمة&lt;/b&gt; (CLASSES، الافتراضي فارغ = جميع الأصناف).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الأصناف المستبعدة&lt;/b&gt; (EXCLUDE_CLASSES، الافتراضي &lt;code&gt;7,18&lt;/code&gt;: الضوضاء المنخفضة والمرتفعة).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الارتدادات الأولى فقط&lt;/b&gt; (FIRST_RETURNS، الافتراضي: لا).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم الخلية&lt;/b&gt; (CELL_SIZE، م، الافتراضي 1)، &lt;b&gt;النطاق&lt;/b&gt; (EXTENT)، &lt;b&gt;نظام الإحداثيات&lt;/b&gt; (CRS): كما في أدوات نموذج الارتفاعات الرقمي للأرض؛ تُهمَل عند تحديد DTM (تُستخدم شبكته ونظام إحداثياته كي يتطابق DSM وDTM خليةً بخلية).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مسافة الملء&lt;/b&gt; (FILL_DISTANCE، م، الافتراضي 0): تأخذ الخلايا الفارغة قيمة أقرب خلية غير فارغة ضمن هذه المسافة؛ 0 = تُترك nodata.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نموذج الارتفاعات الرقمي للأرض&lt;/b&gt; (DTM، راستر اختياري): لازم لحساب nDSM.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تحويل الارتفاعات السالبة إلى 0&lt;/b&gt; (CLAMP_NEGATIVE، الافتراضي: نعم).&lt;/li&gt;&lt;li&gt;&lt;b&gt;DSM&lt;/b&gt; (OUTPUT) و&lt;b&gt;nDSM&lt;/b&gt; (OUTPUT_NDSM، اختياري، يتطلب DTM): GeoTIFF، وقيمة nodata هي −9999.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري).&lt;/li&gt;&lt;/ul&gt;</translation>
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
            <translation>نموذج الارتفاعات الرقمي للأرض DTM (لحساب nDSM؛ تُستخدم شبكته)</translation>
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
            <translation>نظام إحداثيات سحابة النقاط ({}) يختلف عن نظام إحداثيات نموذج الارتفاعات الرقمي ({})؛ استخدم نموذج ارتفاعات رقمياً بنظام إحداثيات سحابة النقاط. لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>The nDSM needs a DTM: give the DTM parameter (e.g. the output of the IDW DTM algorithm). No output was written.</source>
            <translation>يتطلب nDSM نموذج ارتفاعات رقمياً للأرض: حدِّد المعامل DTM (مثلاً مخرج خوارزمية نموذج الارتفاعات الرقمي بطريقة IDW). لم تُكتب أي مخرجات.</translation>
        </message>
    </context>
    <context>
        <name>DtmAccuracyAlgorithm</name>
        <message>
            <source>DTM accuracy against check points</source>
            <translation>دقة نموذج الارتفاعات الرقمي للأرض مقارنةً بنقاط التحقق</translation>
        </message>
        <message>
            <source>dtm,dem,accuracy,rmse,check points,gnss,nmad,asprs,vertical accuracy,validation</source>
            <translation>dtm,dem,الدقة,rmse,نقاط التحقق,gnss,nmad,asprs,الدقة الرأسية,التحقق من الصحة</translation>
        </message>
        <message>
            <source>&lt;p&gt;Compares a DTM with independent check points (e.g. GNSS heights). The DTM is sampled at each point (bilinear by default) and the errors e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; are summarised: N, mean error (bias), MAE, RMSE, standard deviation, max |e|, Pearson r and R² (= r²) between DTM and check heights, NMAD = 1.4826·median|e − median e| (Höhle &amp;amp; Höhle 2009), and the vertical accuracy at 95 % confidence = 1.96·RMSE (ASPRS Positional Accuracy Standards 2014, which assumes unbiased normal errors; the 95th percentile of |e| is reported too). Check points outside the DTM or on nodata are counted and excluded — never read as 0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: DTM=dtm.tif CHECKPOINTS_CSV=gnss.csv → RMSE, r and a report with a scatter plot and an error histogram.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;DTM&lt;/b&gt; (DTM): raster layer; BAND (default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check points&lt;/b&gt; (CHECKPOINTS, optional): point layer; heights from &lt;b&gt;Z_FIELD&lt;/b&gt; or, if empty, from the geometry Z. &lt;b&gt;ID_FIELD&lt;/b&gt; optional.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check point file&lt;/b&gt; (CHECKPOINTS_CSV, optional): delimited text with a header x/easting, y/northing, z/height (and id/name), or columns id x y z without header. Give the layer or the file.&lt;/li&gt;&lt;li&gt;&lt;b&gt;CSV CRS&lt;/b&gt; (CSV_CRS, optional): CRS of the file's coordinates; default = the DTM's CRS.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reproject check points&lt;/b&gt; (REPROJECT, default no): when the check points are in another CRS than the DTM, transform them (x, y only — heights are not converted between vertical datums). Without it such points are an error.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sampling&lt;/b&gt; (METHOD, 0 bilinear (default), 1 nearest cell).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Residuals&lt;/b&gt; (OUTPUT): point layer with id, z_check, z_dtm, error, abs_error and status (used / outside DTM / DTM nodata).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML): HTML with the statistics, a DTM vs check scatter plot, an error histogram and the residual table.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Every statistic is also an output number (N, N_OUTSIDE, N_NODATA, ME, MAE, RMSE, STD, MAX_ABS_ERROR, R, R2, NMAD, ACCURACY_95).&lt;/p&gt;</source>
            <translation>&lt;p&gt;تقارن نموذج الارتفاعات الرقمي للأرض (DTM) بنقاط تحقق مستقلة (مثل ارتفاعات GNSS). يُعتان النموذج عند كل نقطة (بالاستيفاء ثنائي الخطية افتراضياً) وتُلخَّص الأخطاء e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt;: العدد N، ومتوسط الخطأ (الانحياز)، ومتوسط الخطأ المطلق MAE، والجذر التربيعي لمتوسط مربعات الأخطاء RMSE، والانحراف المعياري، وأكبر |e|، ومعامل ارتباط بيرسون r وR² (= r²) بين ارتفاعات النموذج وارتفاعات نقاط التحقق، وNMAD = 1.4826·median|e − median e| (Höhle &amp; Höhle 2009)، والدقة الرأسية عند مستوى ثقة 95 % = 1.96·RMSE (معايير ASPRS للدقة الموضعية 2014، التي تفترض أخطاء طبيعية غير منحازة؛ ويُذكر كذلك المئين 95 لـ|e|). نقاط التحقق الواقعة خارج النموذج أو على خلايا nodata تُعَدّ وتُستبعد — ولا تُقرأ أبداً على أنها 0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: DTM=dtm.tif CHECKPOINTS_CSV=gnss.csv ← RMSE وr وتقرير فيه مخطط انتشار ومدرج تكراري للأخطاء.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;نموذج الارتفاعات الرقمي للأرض&lt;/b&gt; (DTM): طبقة راستر؛ BAND (الافتراضي 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط التحقق&lt;/b&gt; (CHECKPOINTS، اختياري): طبقة نقطية؛ الارتفاعات من &lt;b&gt;Z_FIELD&lt;/b&gt; أو، إن كان فارغاً، من قيمة Z في الهندسة. &lt;b&gt;ID_FIELD&lt;/b&gt; اختياري.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ملف نقاط التحقق&lt;/b&gt; (CHECKPOINTS_CSV، اختياري): نص محدَّد الفواصل بسطر ترويسة x/easting وy/northing وz/height (وid/name)، أو بالأعمدة id x y z دون ترويسة. حدِّد الطبقة أو الملف.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نظام إحداثيات CSV&lt;/b&gt; (CSV_CRS، اختياري): نظام إحداثيات الملف؛ الافتراضي = نظام إحداثيات DTM.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إعادة إسقاط نقاط التحقق&lt;/b&gt; (REPROJECT، الافتراضي: لا): إذا كانت نقاط التحقق بنظام إحداثيات غير نظام DTM تُحوَّل إليه (x وy فقط — لا تُحوَّل الارتفاعات بين المراجع الرأسية). ودون هذا الخيار تُعَدّ هذه النقاط خطأً.&lt;/li&gt;&lt;li&gt;&lt;b&gt;طريقة الاعتيان&lt;/b&gt; (METHOD، 0 ثنائي الخطية (الافتراضي)، 1 أقرب خلية).&lt;/li&gt;&lt;li&gt;&lt;b&gt;البواقي&lt;/b&gt; (OUTPUT): طبقة نقطية بالحقول id وz_check وz_dtm وerror وabs_error وstatus (used / outside DTM / DTM nodata).&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML): ملف HTML بالإحصاءات ومخطط انتشار DTM مقابل نقاط التحقق ومدرج تكراري للأخطاء وجدول البواقي.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;كل إحصائية هي أيضاً مخرج رقمي (N، N_OUTSIDE، N_NODATA، ME، MAE، RMSE، STD، MAX_ABS_ERROR، R، R2، NMAD، ACCURACY_95).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>نموذج الارتفاعات الرقمي للأرض (DTM)</translation>
        </message>
        <message>
            <source>Band</source>
            <translation>الحزمة</translation>
        </message>
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
            <source>Check point file (CSV/TXT)</source>
            <translation>ملف نقاط التحقق (CSV/TXT)</translation>
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
            <source>Residuals</source>
            <translation>البواقي</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <translation>{} بنظام الإحداثيات {} لكن نموذج الارتفاعات الرقمي بنظام {}. أعد إسقاط نقاط التحقق أولاً أو فعِّل الخيار 'إعادة إسقاط نقاط التحقق إلى نظام إحداثيات DTM' (REPROJECT=true؛ x وy فقط، ولا تُحوَّل الارتفاعات). لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>Check points reprojected from {} to {}</source>
            <translation>أُعيد إسقاط نقاط التحقق من {} إلى {}</translation>
        </message>
        <message>
            <source>Check points assumed to be in the DTM's CRS.</source>
            <translation>افتُرض أن نقاط التحقق بنظام إحداثيات نموذج الارتفاعات الرقمي.</translation>
        </message>
        <message>
            <source>Choose a DTM raster.</source>
            <translation>اختر طبقة راستر لنموذج الارتفاعات الرقمي للأرض.</translation>
        </message>
        <message>
            <source>N = {}, RMSE = {:.4f} m, ME = {:.4f} m, r = {:.5f}; {} outside, {} on nodata</source>
            <translation>N = {}، RMSE = {:.4f} م، ME = {:.4f} م، r = {:.5f}؛ {} خارج النموذج، {} على خلايا nodata</translation>
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
            <source>&lt;p&gt;Subtracts an earlier surface from a later one (two DTM/DSM rasters on one grid, or two LAS/LAZ clouds gridded by TIN on a common grid) and keeps the change beyond the level of detection LoD95 = 1.96·√(σ₁² + σ₂²), σ being each epoch's vertical accuracy (e.g. the RMSE of the DTM accuracy tool). Significant cells form cut and fill polygons with area, mean change and volume.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=dtm_2021.tif INPUT_AFTER=dtm_2024.tif SIGMA1=0.08 SIGMA2=0.06.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Before&lt;/b&gt; (INPUT) and &lt;b&gt;After&lt;/b&gt; (INPUT_AFTER): two GeoTIFFs on the same grid, or two LAS/LAZ clouds in one CRS.&lt;/li&gt;&lt;li&gt;&lt;b&gt;σ₁, σ₂&lt;/b&gt; (SIGMA1, SIGMA2, m, default 0.1): vertical accuracy of each epoch.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classes&lt;/b&gt; (CLASSES, clouds only, default &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, clouds only, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum area&lt;/b&gt; (MIN_AREA, m², default 0 = eight cells): smaller regions are dropped (noise alone exceeds the LoD in 5 % of cells).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Difference&lt;/b&gt; (OUTPUT): GeoTIFF after − before (m).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Change polygons&lt;/b&gt; (OUTPUT_POLYGONS, GeoPackage): id, kind (cut / fill), area_m2, mean_change_m, volume_m3.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: LOD, FILL_VOLUME, CUT_VOLUME (m³), N_REGIONS.&lt;/p&gt;</source>
            <translation>&lt;p&gt;يطرح سطحاً سابقاً من سطح لاحق (شبكتا DTM/DSM على شبكة واحدة، أو سحابتا LAS/LAZ تُشبَّكان بـ TIN على شبكة مشتركة) ويحتفظ بالتغيّر الذي يتجاوز حد الكشف LoD95 = 1.96·√(σ₁² + σ₂²)، حيث σ الدقة الرأسية لكل حقبة (مثلاً RMSE من أداة دقة نموذج التضاريس). تكوّن الخلايا المعنوية مضلعات حفر وردم مع المساحة ومتوسط التغيّر والحجم.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=dtm_2021.tif INPUT_AFTER=dtm_2024.tif SIGMA1=0.08 SIGMA2=0.06.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;قبل&lt;/b&gt; (INPUT) و&lt;b&gt;بعد&lt;/b&gt; (INPUT_AFTER): ملفا GeoTIFF على الشبكة نفسها، أو سحابتا LAS/LAZ في نظام إحداثيات واحد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;σ₁ وσ₂&lt;/b&gt; (SIGMA1 وSIGMA2، م، الافتراضي 0.1): الدقة الرأسية لكل حقبة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;الأصناف&lt;/b&gt; (CLASSES، للسحب فقط، الافتراضي &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم الخلية&lt;/b&gt; (CELL_SIZE، م، للسحب فقط، الافتراضي 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أدنى مساحة&lt;/b&gt; (MIN_AREA، م²، الافتراضي 0 = ثماني خلايا): تُحذف المناطق الأصغر (الضوضاء وحدها تتجاوز حد الكشف في 5 % من الخلايا).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الفرق&lt;/b&gt; (OUTPUT): GeoTIFF بعد − قبل (م).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مضلعات التغيّر&lt;/b&gt; (OUTPUT_POLYGONS، GeoPackage): id وkind (حفر / ردم) وarea_m2 وmean_change_m وvolume_m3.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;الأعداد الناتجة: LOD وFILL_VOLUME وCUT_VOLUME (م³) وN_REGIONS.&lt;/p&gt;</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>Accuracy report</source>
            <translation>تقرير الدقة</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>Report as JSON</source>
            <translation>التقرير بصيغة JSON</translation>
        </message>
        <message>
            <source>JSON files (*.json)</source>
            <translation>ملفات JSON (*.json)</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML), &lt;b&gt;residual table&lt;/b&gt; (OUTPUT_CSV: one row per point with v_x, v_y, RMS_i, C_i, pixel residuals, leave-one-out residuals) and &lt;b&gt;JSON&lt;/b&gt; (OUTPUT_JSON: everything, all orders), each optional.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML)، و&lt;b&gt;جدول البواقي&lt;/b&gt; (OUTPUT_CSV: صف لكل نقطة فيه v_x وv_y وRMS_i وC_i والبواقي بالبكسل وبواقي الاستبعاد الفردي) و&lt;b&gt;JSON&lt;/b&gt; (OUTPUT_JSON: كل شيء، لجميع الدرجات)، وكلها اختيارية.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;Every summary figure is also an output number (RMS_T, RMS_T_QGIS, GR, SCALE, LOO_RMS_T, CHECK_RMS_T, RECOMMENDED_ORDER, ACCEPTED, RMS_T_ORDER1…3, …) for the graphical modeler.&lt;/p&gt;</source>
            <translation>&lt;p&gt;كل رقم في الملخص هو أيضاً مخرج رقمي (RMS_T وRMS_T_QGIS وGR وSCALE وLOO_RMS_T وCHECK_RMS_T وRECOMMENDED_ORDER وACCEPTED وRMS_T_ORDER1…3 و…) لاستخدامه في المصمم الرسومي للنماذج.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;Judges a set of ground control points without warping: every transformation (polynomial 1–3, linear, Helmert, projective, thin-plate spline) side by side by the paper's criteria on check points and leave-one-out residuals, with the recommended one and why.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: GCP_FILE=scan.tif.points INPUT=scan.tif TRANSFORMATION=8 GR=0.91 OUTPUT_HTML=report.html OUTPUT_CSV=residuals.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Image&lt;/b&gt; (INPUT, optional): gives the image size (GCPs outside it are an error; quadrants and the plot use its footprint). Without it, give IMAGE_WIDTH and IMAGE_HEIGHT (pixels) or the GCP centroid is used.&lt;/li&gt;</source>
            <translation>&lt;p&gt;تقيِّم مجموعة من نقاط الضبط الأرضي دون تحويل الصورة هندسياً: كل التحويلات (كثيرة الحدود 1–3، الخطي، هلمرت، الإسقاطي، شريحة الصفيحة الرقيقة) جنباً إلى جنب وفق معايير البحث على نقاط التحقق وبواقي ترك واحدة، مع التحويل الموصى به وسبب التوصية.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: GCP_FILE=scan.tif.points INPUT=scan.tif TRANSFORMATION=8 GR=0.91 OUTPUT_HTML=report.html OUTPUT_CSV=residuals.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;الصورة&lt;/b&gt; (INPUT، اختياري): تعطي أبعاد الصورة (نقاط الضبط الواقعة خارجها خطأ؛ وتعتمد الأرباع والمخطط على حدودها). ودونها حدِّد IMAGE_WIDTH وIMAGE_HEIGHT (بالبكسل) وإلا استُخدم مركز ثقل نقاط الضبط.&lt;/li&gt;</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsAlgorithm</name>
        <message>
            <source>LiDAR ground filtering</source>
            <translation>فلترة نقاط الأرض في بيانات الليدار</translation>
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
            <source>&lt;li&gt;&lt;b&gt;GCP file&lt;/b&gt; (GCP_FILE): a QGIS Georeferencer &lt;i&gt;.points&lt;/i&gt; file (mapX,mapY,pixelX,pixelY,enable,…; pixelY is minus the row) or a CSV table with columns id, col,row (or pixel,line; or image_x,image_y in the QGIS sign convention), X,Y (or map_x,map_y / easting,northing) and optional enabled (1/0), role (gcp or check) and weight. Give the file &lt;i&gt;or&lt;/i&gt; a point layer; with neither, the Georeferencer's &lt;i&gt;&amp;lt;image&amp;gt;.points&lt;/i&gt; next to the image is used.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GCP point layer&lt;/b&gt; (GCP_LAYER): points whose geometry holds the map coordinates (in the layer CRS) with fields for the image column and row (COL_FIELD, ROW_FIELD) and optional ID_FIELD, ENABLED_FIELD, ROLE_FIELD, WEIGHT_FIELD (least-squares weights, e.g. 1/σ²; the report uses them, GDAL's warp fits unweighted).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pixel origin&lt;/b&gt; (PIXEL_ORIGIN, default 0 = corner): 0 — image coordinates in the GDAL/QGIS convention, (0,0) is the top-left corner of the image and the centre of the first pixel is (0.5, 0.5); 1 — integer values are pixel centres (0-based array indices), 0.5 is added. Rows always grow downwards (a negative row column is read as QGIS's −row). .points files are always corner-based.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GCP CRS&lt;/b&gt; (GCP_CRS): CRS of the map coordinates when the file has no '#CRS:' line (CSV files never have one). Missing CRS is an error.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Polynomial order&lt;/b&gt; (ORDER, 1–3, default 1): 1 affine (≥ 3 GCPs), 2 (≥ 6), 3 (≥ 10).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground resolution GR&lt;/b&gt; (GR, map units per pixel, optional): pixel size on the ground for the criteria; default sqrt|det J| of the affine fit of the GCPs.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;ملف نقاط الضبط الأرضي&lt;/b&gt; (GCP_FILE): ملف &lt;i&gt;.points&lt;/i&gt; من أداة Georeferencer في QGIS (mapX,mapY,pixelX,pixelY,enable,…؛ وpixelY هو سالب رقم الصف) أو جدول CSV بالأعمدة id وcol,row (أو pixel,line؛ أو image_x,image_y باصطلاح الإشارة في QGIS) وX,Y (أو map_x,map_y / easting,northing) والأعمدة الاختيارية enabled (1/0) وrole (gcp أو check) وweight. حدِّد الملف &lt;i&gt;أو&lt;/i&gt; طبقة نقطية؛ وإن لم يُحدَّد أيٌّ منهما يُستخدم ملف &lt;i&gt;&amp;lt;image&amp;gt;.points&lt;/i&gt; الخاص بأداة Georeferencer المجاور للصورة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;طبقة نقطية لنقاط الضبط&lt;/b&gt; (GCP_LAYER): نقاط تحمل هندستُها الإحداثيات الخرائطية (بنظام إحداثيات الطبقة) مع حقلين لعمود الصورة وصفّها (COL_FIELD وROW_FIELD) والحقول الاختيارية ID_FIELD وENABLED_FIELD وROLE_FIELD وWEIGHT_FIELD (أوزان المربعات الصغرى، مثلاً 1/σ²؛ يستخدمها التقرير، أما التحويل الهندسي (warp) في GDAL فيُوائم دون أوزان).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مبدأ البكسل&lt;/b&gt; (PIXEL_ORIGIN، الافتراضي 0 = الركن): 0 — إحداثيات الصورة باصطلاح GDAL/QGIS، حيث (0,0) هو الركن العلوي الأيسر للصورة ومركز البكسل الأول هو (0.5, 0.5)؛ 1 — القيم الصحيحة هي مراكز البكسلات (فهارس مصفوفة تبدأ من 0)، وتُضاف إليها 0.5. تتزايد الصفوف دائماً نحو الأسفل (يُقرأ عمود الصفوف السالب على أنه −row بحسب اصطلاح QGIS). ملفات .points تعتمد دائماً على الأركان.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نظام إحداثيات نقاط الضبط&lt;/b&gt; (GCP_CRS): نظام الإحداثيات للإحداثيات الخرائطية حين لا يحوي الملف السطر '#CRS:' (ولا تحويه ملفات CSV أبداً). غياب نظام الإحداثيات خطأ.&lt;/li&gt;&lt;li&gt;&lt;b&gt;درجة متعدد الحدود&lt;/b&gt; (ORDER، 1–3، الافتراضي 1): 1 تحويل تآلفي (≥ 3 نقاط ضبط)، 2 (≥ 6)، 3 (≥ 10).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الدقة الأرضية GR&lt;/b&gt; (GR، وحدة خريطة لكل بكسل، اختياري): حجم البكسل على الأرض المستخدم في المعايير؛ الافتراضي sqrt|det J| من المواءمة التآلفية لنقاط الضبط.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Criteria&lt;/b&gt; (Tishreen Univ. J. Eng. Sci. 38(2), 2016): per-point RMS_i and contribution C_i = RMS_i/RMS_T; RMS_x, RMS_y, RMS_T with divisor n (and, labelled, n − N as the QGIS Georeferencer); map scale S = 20000·GR and tolerance band 4·GR … 6·GR for RMS_T; per-point limit 0.25 mm·S = 5·GR; ≥ 68 % (strict 90 %) of points within RMS_T; no directional bias (quadrant sign balance, inner vs edge radial residuals, residual-vector plot). Also: independent check points (role 'check', never fitted), leave-one-out residuals, orders 1–3 side by side with a recommended order (never one whose redundancy n − N is below max(2, ⌈N/2⌉)) and suggested points to drop. Residuals are predicted − given, in map units and pixels.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;المعايير&lt;/b&gt; (مجلة جامعة تشرين للعلوم الهندسية 38(2)، 2016): RMS_i لكل نقطة ومساهمتها C_i = RMS_i/RMS_T؛ وRMS_x وRMS_y وRMS_T بالقسمة على n (وكذلك، مع الإشارة إلى ذلك، على n − N كما في أداة Georeferencer في QGIS)؛ ومقياس الخريطة S = 20000·GR ونطاق السماحية 4·GR … 6·GR لقيمة RMS_T؛ والحد لكل نقطة 0.25 mm·S = 5·GR؛ وأن تقع ≥ 68 % من النقاط (90 % في الصيغة الصارمة) ضمن RMS_T؛ وانعدام الانحياز الاتجاهي (توازن الإشارات بين الأرباع، والبواقي الشعاعية للنقاط الداخلية مقابل نقاط الحواف، ومخطط متجهات البواقي). وأيضاً: نقاط تحقق مستقلة (الدور 'check'، لا تدخل في المواءمة أبداً)، وبواقي الاستبعاد الفردي، والدرجات 1–3 جنباً إلى جنب مع درجة موصى بها (لا تكون أبداً درجةً فائضها n − N أقل من max(2, ⌈N/2⌉)) ونقاط مقترحة للحذف. البواقي = القيمة المتنبأ بها − القيمة المعطاة، بوحدات الخريطة وبالبكسل.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Returns filtered&lt;/b&gt; (RETURNS, default 0 = all): 0 all returns are classified and serve as neighbours (the forest study); 1 last returns only: only last (or single) returns are classified and only they may reject others; first and intermediate returns of multi-return pulses get class 1. Files without return numbers (e.g. the ISPRS samples) count every point as a last return.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, default yes): points far below their neighbours (multipath) get class 7 and take no part in the filter — one stray low point would reject every ground point within r. Advanced: NOISE_RADIUS (m, default 5) and NOISE_THRESHOLD (m, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mode&lt;/b&gt; (MODE, default 0): 0 exact Vosselman rule; 1 terrain-adaptive (&lt;i&gt;this toolbox's extension&lt;/i&gt;): the rule is applied to heights above a smooth low terrain trend (minimum grid of TREND_CELL m, opening and mean filter of TREND_WINDOW m, defaults 10 and 60), so natural slopes steeper than θ are not rejected (ISPRS samp11, steep: total error 21.0 % → 16.4 % at the defaults). Because the terrain slope is removed first, lower θ (about 30–35°) usually works best in this mode.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;الارتدادات المفلترة&lt;/b&gt; (RETURNS، الافتراضي 0 = الكل): 0 تُصنَّف جميع الارتدادات وتُستخدم كلها نقاطاً مجاورة (دراسة الغابات)؛ 1 الارتدادات الأخيرة فقط: لا تُصنَّف إلا الارتدادات الأخيرة (أو المنفردة) ولا يستبعد النقاطَ الأخرى إلا هي؛ وتأخذ الارتدادات الأولى والوسيطة للنبضات متعددة الارتدادات الصنف 1. في الملفات الخالية من أرقام الارتدادات (مثل عيّنات ISPRS) تُعَدّ كل نقطة ارتداداً أخيراً.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إزالة القيم الشاذة المنخفضة أولاً&lt;/b&gt; (NOISE، الافتراضي: نعم): النقاط الواقعة أسفل جيرانها بكثير (بسبب تعدد المسارات) تأخذ الصنف 7 ولا تشارك في الفلترة — فنقطة منخفضة شاردة واحدة كانت ستستبعد كل نقاط الأرض ضمن r. خيارات متقدمة: NOISE_RADIUS (م، الافتراضي 5) وNOISE_THRESHOLD (م، الافتراضي 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;النمط&lt;/b&gt; (MODE، الافتراضي 0): 0 قاعدة Vosselman كما هي؛ 1 متكيِّف مع التضاريس (&lt;i&gt;إضافة من صندوق الأدوات هذا&lt;/i&gt;): تُطبَّق القاعدة على الارتفاعات فوق اتجاه عام منخفض وأملس للتضاريس (شبكة القيم الدنيا بخلية TREND_CELL م، ثم فتح مورفولوجي (opening) وفلتر متوسط بنافذة TREND_WINDOW م، والقيمتان الافتراضيتان 10 و60)، فلا تُستبعد المنحدرات الطبيعية الأشد انحداراً من θ (عيّنة ISPRS samp11 شديدة الانحدار: الخطأ الكلي 21.0 % → 16.4 % بالقيم الافتراضية). ولأن ميل التضاريس يُزال أولاً، فإن قيم θ الأدنى (نحو 30–35°) تعطي عادةً أفضل النتائج في هذا النمط.&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): a .las or .laz file (LAS 1.0–1.4), e.g. the output of a ground filter.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classes used&lt;/b&gt; (CLASSES, default &lt;code&gt;2&lt;/code&gt; = ground): comma-separated LAS classes interpolated; empty = every point. No point of these classes → error that lists the classes present.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 1.0, &amp;gt; 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Extent&lt;/b&gt; (EXTENT, optional): default = the selected points' extent. The grid is snapped outward to multiples of the cell size so that tiles line up.&lt;/li&gt;&lt;li&gt;&lt;b&gt;CRS&lt;/b&gt; (CRS, optional): overrides the CRS of the LAS file. If the file has no CRS and none is given the algorithm stops with an error (a DTM without a CRS is a common source of misplaced data).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Maximum distance to data&lt;/b&gt; (MAX_DISTANCE, m, default 0 = automatic: five mean point spacings, at least two cells): cells whose nearest point is farther are nodata, so no terrain is invented under water, removed buildings or missing strips.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Fill data gaps&lt;/b&gt; (FILL_GAPS, default no): interpolate every cell however far from the data (ignores MAX_DISTANCE).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output&lt;/b&gt; (OUTPUT): GeoTIFF (float32, DEFLATE, nodata −9999) in the input CRS; values belong to cell centres.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): HTML report.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف .las أو .laz (LAS 1.0–1.4)، مثل مخرج أحد فلاتر نقاط الأرض.&lt;/li&gt;&lt;li&gt;&lt;b&gt;الأصناف المستخدمة&lt;/b&gt; (CLASSES، الافتراضي &lt;code&gt;2&lt;/code&gt; = الأرض): أصناف LAS التي تُستوفى، مفصولة بفواصل؛ فارغ = كل النقاط. عدم وجود أي نقطة من هذه الأصناف → خطأ يسرد الأصناف الموجودة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم الخلية&lt;/b&gt; (CELL_SIZE، م، الافتراضي 1.0، &amp;gt; 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;النطاق&lt;/b&gt; (EXTENT، اختياري): الافتراضي = نطاق النقاط المختارة. تُوسَّع الشبكة نحو الخارج لتقع حدودها على مضاعفات حجم الخلية كي تتراصف البلاطات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نظام الإحداثيات&lt;/b&gt; (CRS، اختياري): يحل محل نظام إحداثيات ملف LAS. إذا لم يكن للملف نظام إحداثيات ولم يُحدَّد أي نظام، تتوقف الخوارزمية بخطأ (فنموذج الارتفاعات بلا نظام إحداثيات مصدر شائع لبيانات في غير موضعها).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أقصى مسافة إلى البيانات&lt;/b&gt; (MAX_DISTANCE، م، الافتراضي 0 = تلقائي: خمسة أضعاف متوسط التباعد بين النقاط، وخليتان على الأقل): الخلايا التي تبعد عنها أقرب نقطة أكثر من ذلك تُجعل nodata، فلا تُختلق تضاريس تحت المياه أو المباني المُزالة أو الشرائط المفقودة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ملء فجوات البيانات&lt;/b&gt; (FILL_GAPS، الافتراضي: لا): استيفاء كل خلية مهما بعدت عن البيانات (يتجاهل MAX_DISTANCE).&lt;/li&gt;&lt;li&gt;&lt;b&gt;المخرج&lt;/b&gt; (OUTPUT): GeoTIFF (float32، DEFLATE، nodata −9999) بنظام إحداثيات الإدخال؛ وتعود القيم إلى مراكز الخلايا.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري): تقرير HTML.&lt;/li&gt;</translation>
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
            <source>Pick a loaded point-cloud layer or a .las/.laz file.</source>
            <translation>اختر طبقة سحابة نقاط محمّلة أو ملف ‎.las/.laz‏.</translation>
        </message>
        <message>
            <source>This QGIS build has no PDAL point-cloud provider, so point clouds cannot be loaded as layers: give the .las/.laz file.</source>
            <translation>نسخة QGIS هذه لا تحتوي على مزوّد سحب النقاط PDAL، لذا لا يمكن تحميل سحب النقاط كطبقات: أعطِ ملف ‎.las/.laz‏.</translation>
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
            <source>&lt;li&gt;&lt;b&gt;Classified point cloud&lt;/b&gt; (OUTPUT, .laz/.las): every point with class 2 ground, 1 other or 7 low noise; every other attribute, VLR and the CRS copied unchanged.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground points&lt;/b&gt; (GROUND_OUTPUT, optional): only the ground points.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional) in REPORT_LANGUAGE (advanced).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Keep existing noise classes&lt;/b&gt; (KEEP_NOISE, advanced, default yes): points already classified 7 or 18 keep their class and take no part.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: N_POINTS, N_GROUND, N_NONGROUND, N_NOISE (class 7), POINTS_PER_SECOND (filter step only).&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;سحابة النقاط المصنفة&lt;/b&gt; (OUTPUT، ‎.laz/.las): كل نقطة بالصنف 2 أرض أو 1 أخرى أو 7 ضجيج منخفض؛ وتُنسخ كل السمات الأخرى وسجلات VLR ونظام الإحداثيات دون تغيير.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط الأرض&lt;/b&gt; (GROUND_OUTPUT، اختياري): نقاط الأرض فقط.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري) بلغة REPORT_LANGUAGE (متقدم).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الإبقاء على أصناف الضجيج الموجودة&lt;/b&gt; (KEEP_NOISE، متقدم، الافتراضي نعم): النقاط المصنفة مسبقاً 7 أو 18 تحتفظ بصنفها ولا تشارك.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;الأرقام المُخرَجة: N_POINTS، N_GROUND، N_NONGROUND، N_NOISE (الصنف 7)، POINTS_PER_SECOND (خطوة المرشح فقط).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Transformation&lt;/b&gt; (TRANSFORMATION, default 0): 0 polynomial of order ORDER; 1–3 polynomial of order 1, 2, 3; 4 linear (shift and scale per axis, ≥ 2 GCPs); 5 Helmert (shift, one scale, one rotation, ≥ 2); 6 projective (homography, ≥ 4); 7 thin-plate spline (through every GCP, ≥ 3, as gdalwarp -tps); 8 recommended: every transformation is compared and the one with the lowest check-point (else leave-one-out) error is used, the simplest within 10 % of the best.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Refine GCPs&lt;/b&gt; (REFINE, default off): as gdalwarp -refine_gcps, drop the GCP with the largest residual while it exceeds the tolerance, then refit; the dropped points are listed in the report.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Refinement tolerance&lt;/b&gt; (REFINE_TOLERANCE, map units, default the C5 per-point limit 0.25 mm·S = 5·GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum GCPs&lt;/b&gt; (MIN_GCPS, default the transformation's minimum + 2): the refinement never goes below this count.&lt;/li&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;التحويل&lt;/b&gt; (TRANSFORMATION، الافتراضي 0): 0 كثيرة حدود من الدرجة ORDER؛ 1–3 كثيرة حدود من الدرجة 1 أو 2 أو 3؛ 4 خطي (إزاحة ومقياس لكل محور، ≥ 2 نقطة)؛ 5 هلمرت (إزاحة ومقياس واحد ودوران واحد، ≥ 2)؛ 6 إسقاطي (تحويل متجانس، ≥ 4)؛ 7 شريحة الصفيحة الرقيقة (تمر بكل نقطة، ≥ 3، مثل gdalwarp -tps)؛ 8 الموصى به: تُقارَن جميع التحويلات ويُستخدم صاحب أصغر خطأ على نقاط التحقق (وإلا على ترك واحدة خارجاً)، والأبسط ضمن 10 % من الأفضل.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تنقيح النقاط&lt;/b&gt; (REFINE، الافتراضي معطّل): كما في gdalwarp -refine_gcps، تُحذف النقطة ذات أكبر باقٍ ما دام يتجاوز التسامح ثم يُعاد الملاءمة؛ وتُسرد النقاط المحذوفة في التقرير.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تسامح التنقيح&lt;/b&gt; (REFINE_TOLERANCE، بوحدات الخريطة، الافتراضي حدّ النقطة C5 أي 0.25 مم·S = 5·GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أدنى عدد للنقاط&lt;/b&gt; (MIN_GCPS، الافتراضي الحدّ الأدنى للتحويل + 2): لا ينزل التنقيح تحت هذا العدد.&lt;/li&gt;</translation>
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
    </context>
    <context>
        <name>GroundFilterAccuracyAlgorithm</name>
        <message>
            <source>Ground filter accuracy</source>
            <translation>دقة فلتر نقاط الأرض</translation>
        </message>
        <message>
            <source>lidar,ground,filter,accuracy,type i,type ii,total error,kappa,isprs,reference,confusion matrix</source>
            <translation>ليدار,أرض,فلتر,الدقة,النوع الأول,النوع الثاني,الخطأ الكلي,كابا,isprs,مرجع,مصفوفة الالتباس</translation>
        </message>
        <message>
            <source>&lt;p&gt;Compares a filtered point cloud with reference labels, with the measures of the ISPRS filter test (Sithole &amp;amp; Vosselman 2004): the cross matrix a (ground kept), b (ground rejected), c (object accepted), d (object rejected), Type I = b/(a+b), Type II = c/(c+d), total = (b+c)/n and Cohen's kappa.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=classified.laz REFERENCE=samp54.laz (the ISPRS reference sample, class 2 = ground) OUTPUT_HTML=accuracy.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Filtered point cloud&lt;/b&gt; (INPUT, LAS/LAZ).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Class dimension of the filtered cloud&lt;/b&gt; (FIELD, default classification) and its &lt;b&gt;ground classes&lt;/b&gt; (GROUND_CLASSES, default 2; a list such as 2,8 is accepted). Every other class (1, 7 noise, 0...) counts as object.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reference point cloud&lt;/b&gt; (REFERENCE, optional): the same points in the same order (checked: equal count and coordinates). When empty, the reference labels are read from another dimension of INPUT.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reference class dimension&lt;/b&gt; (REFERENCE_FIELD, default classification; e.g. user_data or an extra dimension when there is no reference cloud) and its &lt;b&gt;ground classes&lt;/b&gt; (REFERENCE_GROUND_CLASSES, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): the matrix, the errors, and the reference labels of every filtered class.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Per-point error layer&lt;/b&gt; (ERROR_OUTPUT, optional LAS/LAZ): a copy of INPUT, every attribute unchanged except &lt;i&gt;user_data&lt;/i&gt; = 0 correct, 1 Type I (ground rejected), 2 Type II (object accepted); style the point cloud layer by user_data to map where the filter fails.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Outputs A, B, C, D, N, TYPE1, TYPE2, TOTAL and KAPPA are numbers for the graphical modeler.&lt;/p&gt;</source>
            <translation>&lt;p&gt;تقارن سحابة نقاط مفلترة بتصنيفات مرجعية، بمقاييس اختبار فلاتر ISPRS (Sithole &amp; Vosselman 2004): مصفوفة التقاطع a (أرض مُبقاة)، b (أرض مرفوضة)، c (أجسام مقبولة)، d (أجسام مرفوضة)، والنوع الأول = b/(a+b)، والنوع الثاني = c/(c+d)، والخطأ الكلي = (b+c)/n، ومعامل كابا لكوهين.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=classified.laz REFERENCE=samp54.laz (عيّنة ISPRS المرجعية، الصنف 2 = أرض) OUTPUT_HTML=accuracy.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط المفلترة&lt;/b&gt; (INPUT، LAS/LAZ).&lt;/li&gt;&lt;li&gt;&lt;b&gt;بُعد الصنف في السحابة المفلترة&lt;/b&gt; (FIELD، الافتراضي classification) و&lt;b&gt;أصناف الأرض&lt;/b&gt; فيها (GROUND_CLASSES، الافتراضي 2؛ تُقبل قائمة مثل 2,8). أي صنف آخر (1، 7 ضوضاء، 0...) يُعَدّ جسماً.&lt;/li&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط المرجعية&lt;/b&gt; (REFERENCE، اختياري): النقاط نفسها وبالترتيب نفسه (يُتحقَّق من تساوي العدد والإحداثيات). إذا تُركت فارغة تُقرأ التصنيفات المرجعية من بُعد آخر في INPUT.&lt;/li&gt;&lt;li&gt;&lt;b&gt;بُعد الصنف في المرجع&lt;/b&gt; (REFERENCE_FIELD، الافتراضي classification؛ مثلاً user_data أو بُعد إضافي عند عدم وجود سحابة مرجعية) و&lt;b&gt;أصناف الأرض&lt;/b&gt; فيه (REFERENCE_GROUND_CLASSES، الافتراضي 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري): المصفوفة والأخطاء والتصنيفات المرجعية لكل صنف بعد الفلترة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;طبقة الخطأ لكل نقطة&lt;/b&gt; (ERROR_OUTPUT، ملف LAS/LAZ اختياري): نسخة من INPUT بكل خصائصها دون تغيير عدا &lt;i&gt;user_data&lt;/i&gt; = 0 صحيح، 1 النوع الأول (أرض مرفوضة)، 2 النوع الثاني (جسم مقبول)؛ نسِّق طبقة سحابة النقاط حسب user_data لترى على الخريطة أين يخفق الفلتر.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;المخرجات A وB وC وD وN وTYPE1 وTYPE2 وTOTAL وKAPPA أرقام تُستخدم في المصمم الرسومي للنماذج.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Filtered point cloud (LAS/LAZ)</source>
            <translation>سحابة النقاط المفلترة (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Class dimension of the filtered cloud</source>
            <translation>بُعد الصنف في السحابة المفلترة</translation>
        </message>
        <message>
            <source>Ground classes of the filtered cloud</source>
            <translation>أصناف الأرض في السحابة المفلترة</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
        </message>
        <message>
            <source>Per-point error layer (user_data: 0 correct, 1 Type I, 2 Type II)</source>
            <translation>طبقة الخطأ لكل نقطة (user_data: 0 صحيح، 1 النوع الأول، 2 النوع الثاني)</translation>
        </message>
        <message>
            <source>The error layer must end in .las or .laz: {p}</source>
            <translation>يجب أن ينتهي اسم ملف طبقة الخطأ بالامتداد .las أو .laz: {p}</translation>
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
            <source>&lt;p&gt;Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) with no parameter to set: a progressive morphological filter (Pingel et al. 2013, after Zhang et al. 2003) whose raster cell and slope tolerance are derived from the cloud itself (point density, terrain slope), followed by three passes that rebuild the terrain from the points accepted and re-test every point against it.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz — nothing else.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Measured accuracy&lt;/b&gt; (total error, Sithole &amp;amp; Vosselman 2004) on the 8 ISPRS filter-test samples 11, 12, 22, 31, 41, 53, 54, 61: mean 4.06 % at these defaults; SMRF with PDAL's defaults 5.75 % in the same script. The defaults were chosen on these samples: the honest, cross-validated figure (leave one sample out) is 4.42 %; worst sample 9.82 % (samp11, steep terrain with buildings). Beats SMRF on 5 of the 8 samples.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz in a projected CRS (metres); 0.2 to 20+ points/m².&lt;/li&gt;&lt;li&gt;Advanced overrides (0 = derived from the cloud): &lt;b&gt;CELL&lt;/b&gt; (m, default 0 → 1 m), &lt;b&gt;MAX_WINDOW&lt;/b&gt; (m, default 18; must exceed the largest building), &lt;b&gt;SLOPE&lt;/b&gt; (rise/run, default 0 → 0.5 × local terrain slope, 0.10 to 0.60), &lt;b&gt;THRESHOLD&lt;/b&gt; (m, default 0.5; plus 1.25 m per unit of terrain slope), &lt;b&gt;REFINE&lt;/b&gt; (passes, default 3).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, advanced, default no): the filter finds low noise itself; yes runs the shared pre-filter first (NOISE_RADIUS m, default 5; NOISE_THRESHOLD m, default 1).&lt;/li&gt;</source>
            <translation>&lt;p&gt;يصنّف سحابة نقاط LAS/LAZ إلى أرض (الصنف 2) ونقاط أخرى (الصنف 1) وضجيج منخفض (الصنف 7) دون أي معامل يجب ضبطه: مرشح مورفولوجي تدريجي (Pingel وآخرون 2013، بعد Zhang وآخرين 2003) تُشتق خلية شبكته النقطية وسماحية انحداره من السحابة نفسها (كثافة النقاط، انحدار التضاريس)، تليه ثلاث تمريرات تعيد بناء التضاريس من النقاط المقبولة وتعيد اختبار كل نقطة مقابلها.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz — لا شيء غير ذلك.&lt;/p&gt;&lt;p&gt;&lt;b&gt;الدقة المقيسة&lt;/b&gt; (الخطأ الكلي، Sithole &amp;amp; Vosselman 2004) على عينات اختبار المرشحات الثماني من ISPRS ‏11، 12، 22، 31، 41، 53، 54، 61: المتوسط 4.06 % بهذه القيم الافتراضية؛ وSMRF بقيم PDAL الافتراضية 5.75 % في البرنامج نفسه. اختيرت القيم الافتراضية على هذه العينات: الرقم الصادق بالتحقق المتقاطع (ترك عينة واحدة خارجاً) هو 4.42 %؛ أسوأ عينة 9.82 % (samp11، تضاريس شديدة الانحدار مع مبانٍ). يتفوق على SMRF في 5 من 8 عينات.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف ‎.las أو ‎.laz في نظام إحداثيات مسقط (أمتار)؛ من 0.2 إلى أكثر من 20 نقطة/م².&lt;/li&gt;&lt;li&gt;تجاوزات متقدمة (0 = مشتقة من السحابة): &lt;b&gt;CELL&lt;/b&gt; (م، الافتراضي 0 ← 1 م)، &lt;b&gt;MAX_WINDOW&lt;/b&gt; (م، الافتراضي 18؛ يجب أن يتجاوز أكبر مبنى)، &lt;b&gt;SLOPE&lt;/b&gt; (ارتفاع/مسافة، الافتراضي 0 ← 0.5 × انحدار التضاريس المحلي، من 0.10 إلى 0.60)، &lt;b&gt;THRESHOLD&lt;/b&gt; (م، الافتراضي 0.5؛ زائد 1.25 م لكل وحدة من انحدار التضاريس)، &lt;b&gt;REFINE&lt;/b&gt; (تمريرات، الافتراضي 3).&lt;/li&gt;&lt;li&gt;&lt;b&gt;إزالة النقاط الشاذة المنخفضة أولاً&lt;/b&gt; (NOISE، متقدم، الافتراضي لا): يجد المرشح الضجيج المنخفض بنفسه؛ نعم تشغّل المرشح المسبق المشترك أولاً (NOISE_RADIUS م، الافتراضي 5؛ NOISE_THRESHOLD م، الافتراضي 1).&lt;/li&gt;</translation>
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
            <source>Height tolerance (m)</source>
            <translation>سماحية الارتفاع (م)</translation>
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
            <source>Recommended ground filter: window {} m, threshold {} m, {} refinement passes</source>
            <translation>مرشح الأرض الموصى به: نافذة {} م، عتبة {} م، {} تمريرات تحسين</translation>
        </message>
    </context>
    <context>
        <name>GsdBatchAlgorithm</name>
        <message>
            <source>GSD and photogrammetric accuracy calculator (batch table)</source>
            <translation>حاسبة GSD والدقة التصويرية (جدول دفعي)</translation>
        </message>
        <message>
            <source>&lt;p&gt;Runs the GSD / accuracy calculator for every row of a table (CSV, spreadsheet or any layer) and writes a table with the inputs and all results.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Input columns&lt;/b&gt; (case-insensitive): &lt;i&gt;camera&lt;/i&gt; (optional preset key: nikon_p100, dji_p4rtk, dji_p1_35, phaseone_ixm100_80), &lt;i&gt;distance&lt;/i&gt; (m, required), &lt;i&gt;sensor_width&lt;/i&gt; (mm), &lt;i&gt;image_width&lt;/i&gt; (px), &lt;i&gt;focal_length&lt;/i&gt; (mm) — required unless a camera preset is given — and optionally sensor_height, image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, forward_overlap, side_overlap, stereo_base (units as in the single calculator).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Output&lt;/b&gt;: the input columns plus gsd_cm, footprint_width_m, sigma_xyz_mm, dense_resolution_cm and every other result. A row with an invalid value stops the run with an error naming the row and column.&lt;/p&gt;</source>
            <translation>&lt;p&gt;تشغّل حاسبة GSD والدقة لكل سطر من جدول (CSV أو جدول بيانات أو أي طبقة) وتكتب جدولاً بالمدخلات وجميع النتائج.&lt;/p&gt;&lt;p&gt;&lt;b&gt;أعمدة الإدخال&lt;/b&gt; (دون تمييز حالة الأحرف): &lt;i&gt;camera&lt;/i&gt; (اختياري، مفتاح كاميرا معرّفة: nikon_p100، dji_p4rtk، dji_p1_35، phaseone_ixm100_80)، &lt;i&gt;distance&lt;/i&gt; (م، إلزامي)، &lt;i&gt;sensor_width&lt;/i&gt; (مم)، &lt;i&gt;image_width&lt;/i&gt; (بكسل)، &lt;i&gt;focal_length&lt;/i&gt; (مم) — إلزامية ما لم تُحدَّد كاميرا — واختيارياً sensor_height وimage_height وtarget_gsd وk_m وk_s وpyramid_level وsubsampling_step وobserved_sx وobserved_sy وobserved_sz وobserved_sxyz وobserved_dense_std وforward_overlap وside_overlap وstereo_base (بالوحدات نفسها كما في الحاسبة المفردة).&lt;/p&gt;&lt;p&gt;&lt;b&gt;المخرج&lt;/b&gt;: أعمدة الإدخال مضافاً إليها gsd_cm وfootprint_width_m وsigma_xyz_mm وdense_resolution_cm وسائر النتائج. السطر الذي يحوي قيمة غير صالحة يوقف التشغيل برسالة تذكر السطر والعمود.&lt;/p&gt;</translation>
        </message>
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
            <source>&lt;p&gt;&lt;b&gt;Round GSD like the paper&lt;/b&gt; (ROUND_GSD, default no): round the GSD to 0.01 cm/px before the derived quantities.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;تقريب GSD كما في البحث&lt;/b&gt; (ROUND_GSD، الافتراضي: لا): يقرّب GSD إلى 0.01 سم/بكسل قبل حساب الكميات المشتقة.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Could not write the result table: {0}</source>
            <translation>تعذّرت كتابة جدول النتائج: {0}</translation>
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
            <translation>ارتفاع الحساس (مم)</translation>
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
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>&lt;p&gt;Computes the ground sampling distance (GSD) and footprint of a camera at a given distance or flying height. It also gives the theoretical accuracy of phototriangulation and of a dense-matching cloud, and compares observed accuracies with it (Al Khalil 2019).&lt;/p&gt;</source>
            <translation>&lt;p&gt;يحسب المسافة الأرضية للعيّنة (GSD) والتغطية الأرضية لكاميرا على مسافة أو ارتفاع طيران معيّن. ويعطي أيضًا الدقة النظرية للتثليث الجوي ولسحابة المطابقة الكثيفة، ويقارن الدقة المرصودة بها (الخليل 2019).&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: the paper's Nikon Coolpix P100 at 5.88 m (sensor width 6.123 mm, image width 3648 px, focal length 4.6 mm) gives a GSD of 0.21455 cm/px, σ&lt;sub&gt;xyz&lt;/sub&gt; 1.287 mm (1.26 mm with the rounded GSD), a dense-cloud resolution of 0.858 cm and a footprint 7.827 m wide.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: كاميرا Nikon Coolpix P100 في البحث على مسافة ‎5.88 m‏ (عرض المستشعر ‎6.123 mm‏، عرض الصورة ‎3648 px‏، البعد البؤري ‎4.6 mm‏) تعطي GSD مقدارها ‎0.21455 cm/px‏، و σ&lt;sub&gt;xyz&lt;/sub&gt; ‎1.287 mm‏ (‎1.26 mm‏ مع GSD المقرّبة)، ودقة سحابة كثيفة ‎0.858 cm‏، وتغطية أرضية بعرض ‎7.827 m‏.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Formulas&lt;/b&gt;: GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;); footprint = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;; σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD; σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;; matching step P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;; dense resolution R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;الصيغ&lt;/b&gt;: &lt;span dir="ltr"&gt;GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;)&lt;/span&gt;؛ التغطية = &lt;span dir="ltr"&gt;D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;&lt;/span&gt;؛ خطوة المطابقة &lt;span dir="ltr"&gt;P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;&lt;/span&gt;؛ دقة السحابة الكثيفة &lt;span dir="ltr"&gt;R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD&lt;/span&gt;.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Camera preset&lt;/b&gt; (default Custom): fills the sensor, image and focal length values; values you enter override the preset.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Distance&lt;/b&gt; (m, default 100): camera–object distance or flying height above ground, &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor width&lt;/b&gt; (mm), &lt;b&gt;image width&lt;/b&gt; (px) and &lt;b&gt;focal length&lt;/b&gt; (mm, the true focal length, not the 35 mm equivalent): required with the Custom camera.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor height&lt;/b&gt; (mm) / &lt;b&gt;image height&lt;/b&gt; (px): optional, for the footprint height and the flight spacing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Target GSD&lt;/b&gt; (cm/px): optional; gives the distance that achieves it.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Round GSD like the paper&lt;/b&gt; (default no): round the GSD to 0.01 cm/px before the derived quantities.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (px, default 0.3; 0.13 for an expert operator) and &lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pyramid level N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (default 0.5, a fraction in (0, 1], or a percentage) and &lt;b&gt;subsampling step T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (px, ≥ 1, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Observed σx, σy, σz, σxyz&lt;/b&gt; (mm) and &lt;b&gt;observed dense-cloud std&lt;/b&gt; (cm): optional; give the observed/theoretical ratios.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Extension&lt;/b&gt; (not in the paper): stereo base (m) gives the normal-case σ&lt;sub&gt;Z&lt;/sub&gt;; forward/side overlap (%) give the exposure and line spacing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GSD calculator report&lt;/b&gt;: optional HTML report.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Every result is also an output number, so the graphical modeler can chain it.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;الكاميرا المعرّفة مسبقًا&lt;/b&gt; (الافتراضي: مخصّص): تملأ قيم المستشعر والصورة والبعد البؤري؛ والقيم التي تُدخلها تتقدّم عليها.&lt;/li&gt;&lt;li&gt;&lt;b&gt;المسافة&lt;/b&gt; (m، الافتراضي 100): المسافة بين الكاميرا والجسم أو ارتفاع الطيران فوق الأرض، &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عرض المستشعر&lt;/b&gt; (mm) و&lt;b&gt;عرض الصورة&lt;/b&gt; (px) و&lt;b&gt;البعد البؤري&lt;/b&gt; (mm، البعد البؤري الحقيقي لا المكافئ لـ 35 mm): مطلوبة مع الكاميرا «المخصّصة».&lt;/li&gt;&lt;li&gt;&lt;b&gt;ارتفاع المستشعر&lt;/b&gt; (mm) / &lt;b&gt;ارتفاع الصورة&lt;/b&gt; (px): اختياريان، لارتفاع التغطية ولتباعد الطيران.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GSD المستهدفة&lt;/b&gt; (cm/px): اختيارية؛ تعطي المسافة التي تحققها.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تقريب GSD كما في البحث&lt;/b&gt; (الافتراضي: لا): تقريب GSD إلى ‎0.01 cm/px‏ قبل حساب الكميات المشتقة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (px، الافتراضي 0.3؛ و0.13 لمشغّل خبير) و&lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (الافتراضي 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مستوى الهرم N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (الافتراضي 0.5، كسر في (0، 1]، أو نسبة مئوية) و&lt;b&gt;خطوة الاعتيان T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (px، ≥ 1، الافتراضي 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;σx وσy وσz وσxyz المرصودة&lt;/b&gt; (mm) و&lt;b&gt;الانحراف المعياري المرصود للسحابة الكثيفة&lt;/b&gt; (cm): اختيارية؛ تعطي نسب المرصود إلى النظري.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إضافة&lt;/b&gt; (ليست في البحث): قاعدة الاستريو (m) تعطي σ&lt;sub&gt;Z&lt;/sub&gt; للحالة العادية؛ والتداخل الأمامي/الجانبي (%) يعطي تباعد اللقطات وتباعد خطوط الطيران.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تقرير حاسبة GSD&lt;/b&gt;: تقرير HTML اختياري.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;كل نتيجة هي أيضًا رقم ناتج، فيمكن ربطها في المُنمذج الرسومي.&lt;/p&gt;</translation>
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
    </context>
    <context>
        <name>IdwDtmAlgorithm</name>
        <message>
            <source>DTM by inverse distance weighting (IDW)</source>
            <translation>نموذج الارتفاعات الرقمي للأرض بطريقة مقلوب المسافة الموزون (IDW)</translation>
        </message>
        <message>
            <source>dtm,dem,idw,inverse distance,interpolation,lidar,ground,gdal_grid,invdistnn,raster</source>
            <translation>dtm,dem,idw,مقلوب المسافة,الاستيفاء,ليدار,أرض,gdal_grid,invdistnn,راستر</translation>
        </message>
        <message>
            <source>&lt;p&gt;Interpolates a terrain raster from the ground points of a LAS/LAZ file by inverse distance weighting (Shepard 1968): ẑ = Σ w&lt;sub&gt;i&lt;/sub&gt; z&lt;sub&gt;i&lt;/sub&gt; / Σ w&lt;sub&gt;i&lt;/sub&gt;, w&lt;sub&gt;i&lt;/sub&gt; = 1/d&lt;sub&gt;i&lt;/sub&gt;&lt;sup&gt;p&lt;/sup&gt;, over the nearest neighbours of each cell centre. Same semantics as &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; (power, max_points, radius, min_points; a cell centre on a point takes its height exactly), but KD-tree based and processed in blocks: 1 M points onto 1 M cells take seconds.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=1 POWER=3 NEIGHBOURS=12 (the seed paper's best setting, RMSE 0.204 m at 62 GNSS points).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</source>
            <translation>&lt;p&gt;تستوفي راستر تضاريس من نقاط الأرض في ملف LAS/LAZ بطريقة مقلوب المسافة الموزون (Shepard 1968): ẑ = Σ w&lt;sub&gt;i&lt;/sub&gt; z&lt;sub&gt;i&lt;/sub&gt; / Σ w&lt;sub&gt;i&lt;/sub&gt;، w&lt;sub&gt;i&lt;/sub&gt; = 1/d&lt;sub&gt;i&lt;/sub&gt;&lt;sup&gt;p&lt;/sup&gt;، على أقرب الجيران لمركز كل خلية. الدلالة نفسها كما في &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; (power وmax_points وradius وmin_points؛ ومركز الخلية الواقع على نقطة يأخذ ارتفاعها بالضبط)، لكن بالاعتماد على شجرة KD وبالمعالجة على كتل: 1 مليون نقطة على 1 مليون خلية تستغرق ثوانيَ.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=1 POWER=3 NEIGHBOURS=12 (أفضل إعداد في البحث المرجعي، RMSE = 0.204 م على 62 نقطة GNSS).&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</translation>
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
            <translation>نموذج الارتفاعات الرقمي للأرض بطريقة IDW</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Power&lt;/b&gt; (POWER, default 2; the paper found 3 best).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Neighbours&lt;/b&gt; (NEIGHBOURS, default 12): nearest points used (gdal max_points); 0 = all points within the radius (needs RADIUS). More neighbours than points → error.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Search radius&lt;/b&gt; (RADIUS, m, default 0 = unlimited): only points within it are used (gdal radius).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum points&lt;/b&gt; (MIN_POINTS, default 0): cells with fewer neighbours within the radius are nodata (gdal min_points).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Outputs also the numbers N_POINTS, VALID_CELLS, NODATA_CELLS.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;الأس&lt;/b&gt; (POWER، الافتراضي 2؛ وجد البحث أن 3 هو الأفضل).&lt;/li&gt;&lt;li&gt;&lt;b&gt;عدد الجيران&lt;/b&gt; (NEIGHBOURS، الافتراضي 12): عدد أقرب النقاط المستخدمة (max_points في gdal)؛ 0 = كل النقاط ضمن نصف القطر (يتطلب RADIUS). عدد جيران أكبر من عدد النقاط → خطأ.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نصف قطر البحث&lt;/b&gt; (RADIUS، م، الافتراضي 0 = غير محدود): لا تُستخدم إلا النقاط الواقعة ضمنه (radius في gdal).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الحد الأدنى لعدد النقاط&lt;/b&gt; (MIN_POINTS، الافتراضي 0): الخلايا التي لها جيران أقل من ذلك ضمن نصف القطر تُجعل nodata (min_points في gdal).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;تُخرج أيضاً الأرقام N_POINTS وVALID_CELLS وNODATA_CELLS.&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>KrigingDtmAlgorithm</name>
        <message>
            <source>DTM by kriging (ordinary / universal)</source>
            <translation>نموذج الارتفاعات الرقمي للأرض بطريقة الكريغينغ (العادي / الشامل)</translation>
        </message>
        <message>
            <source>dtm,dem,kriging,variogram,geostatistics,pykrige,interpolation,lidar,variance,cross-validation</source>
            <translation>dtm,dem,كريغينغ,فاريوغرام,الإحصاء الجغرافي,pykrige,الاستيفاء,ليدار,التباين,التحقق المتقاطع</translation>
        </message>
        <message>
            <source>&lt;p&gt;Kriging (Matheron 1963; Cressie 1993) of the ground points of a LAS/LAZ file onto a raster, with a kriging variance (or standard deviation) raster. Ordinary kriging (unknown constant mean) or universal kriging with a linear drift. The variogram is fitted with PyKrige's estimator on a random subsample (or given by you); each cell is then kriged from its nearest points in batched local systems, so 1 M points onto a 1 km² grid at 1 m take about a minute instead of the n×n matrix that makes plain PyKrige run out of memory past ~100 k points.&lt;/p&gt;&lt;p&gt;&lt;b&gt;What is approximated&lt;/b&gt;: the variogram is fitted on a sample of point pairs (FIT_POINTS, reproducible with SEED), by default at the local scale. Local-neighbourhood kriging is not global kriging: only the NEIGHBOURS nearest points are weighted and the mean is re-estimated in every neighbourhood (quasi-stationarity). On terrain this follows the relief better than one global mean (it gave the lowest hold-out RMSE on all four ISPRS samples in the benchmark), but the two differ — typically by centimetres, by decimetres to metres at borders, gaps and steep slopes. With NEIGHBOURS equal to the number of points (≤ 6000) the result is global kriging, identical to PyKrige. With a linear drift the variogram is fitted on the residuals of a least-squares plane; points with identical x, y are merged (mean height). The kriging variance is model-based: check it with CV_POINTS (RMS standardised error near 1 means realistic variances).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground.laz CELL_SIZE=1 VARIOGRAM=spherical NEIGHBOURS=16 CV_POINTS=1000.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</source>
            <translation>&lt;p&gt;كريغينغ (Matheron 1963؛ Cressie 1993) لنقاط الأرض في ملف LAS/LAZ على راستر، مع راستر لتباين الكريغينغ (أو انحرافه المعياري). كريغينغ عادي (متوسط ثابت مجهول) أو كريغينغ شامل بانجراف خطي. يُوائَم الفاريوغرام بمقدِّر PyKrige على عيّنة جزئية عشوائية (أو تحدده أنت)؛ ثم تُقدَّر كل خلية بالكريغينغ من أقرب النقاط إليها في أنظمة محلية تُحل على دفعات، فتستغرق 1 مليون نقطة على شبكة مساحتها 1 كم² بخلايا 1 م نحو دقيقة، بدلاً من المصفوفة n×n التي تجعل PyKrige المعتاد يستنفد الذاكرة بعد نحو 100 ألف نقطة.&lt;/p&gt;&lt;p&gt;&lt;b&gt;ما الذي يُقرَّب&lt;/b&gt;: يُوائَم الفاريوغرام على عيّنة من أزواج النقاط (FIT_POINTS، قابلة للتكرار بـSEED)، على المقياس المحلي افتراضياً. الكريغينغ ضمن جوار محلي ليس كريغينغاً كلّياً: تُرجَّح فقط أقرب NEIGHBOURS نقطة ويُعاد تقدير المتوسط في كل جوار (شبه استقرارية). على التضاريس يتبع هذا الأسلوب شكل السطح أفضل من متوسط كلّي واحد (أعطى أدنى RMSE على النقاط المحجوزة للاختبار في عيّنات ISPRS الأربع جميعها في اختبار الأداء)، لكن الطريقتين تختلفان — عادةً ببضعة سنتيمترات، وبعشرات السنتيمترات حتى أمتار عند الحواف والفجوات والمنحدرات الشديدة. وعندما تساوي NEIGHBOURS عدد النقاط (≤ 6000) تكون النتيجة كريغينغاً كلّياً مطابقاً لـPyKrige. ومع الانجراف الخطي يُوائَم الفاريوغرام على بواقي مستوٍ بالمربعات الصغرى؛ وتُدمج النقاط ذات x وy المتطابقة (بمتوسط الارتفاع). تباين الكريغينغ مبني على النموذج: تحقق منه باستخدام CV_POINTS (قيمة RMS للأخطاء المعيَّرة القريبة من 1 تعني تباينات واقعية).&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground.laz CELL_SIZE=1 VARIOGRAM=spherical NEIGHBOURS=16 CV_POINTS=1000.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</translation>
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
            <translation>نموذج الارتفاعات الرقمي للأرض بطريقة الكريغينغ</translation>
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
            <source>&lt;li&gt;&lt;b&gt;Kriging type&lt;/b&gt; (KRIGING_TYPE, 0 ordinary (default), 1 universal with linear drift).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Variogram model&lt;/b&gt; (VARIOGRAM, 0 linear, 1 power, 2 gaussian, 3 spherical (default), 4 exponential).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Variogram&lt;/b&gt; (VARIOGRAM_NUGGET m², VARIOGRAM_SILL m², VARIOGRAM_RANGE m; linear: VARIOGRAM_SLOPE; power: VARIOGRAM_SCALE, VARIOGRAM_EXPONENT; all optional numbers). Empty = fitted automatically. The sill includes the nugget; the range is the practical range.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Neighbours&lt;/b&gt; (NEIGHBOURS, default 16, ≥ 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Points for the variogram fit&lt;/b&gt; (FIT_POINTS, default 3000).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Lag classes&lt;/b&gt; (NLAGS, default 12) and &lt;b&gt;maximum lag&lt;/b&gt; (MAX_LAG, m, default 0 = automatic: three times the typical distance to the NEIGHBOURS-th neighbour, the scale local kriging uses, so the nugget and the short-range shape that set the weights and the variance are well sampled; the fitted sill and range then describe that local scale). For a classical field-scale fit give e.g. half the extent (Journel &amp;amp; Huijbregts 1978). A fitted nugget is raised to at least 1 % of the semivariance at the maximum lag, for numerical stability (Gaussian and power models).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cross-validation points&lt;/b&gt; (CV_POINTS, default 0 = off): leave-one-out on this many random points; reports ME, RMSE, mean standardised error (ideal 0) and RMS standardised error (ideal 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Seed&lt;/b&gt; (SEED, default 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Variance output&lt;/b&gt; (OUTPUT_VARIANCE, optional GeoTIFF): kriging variance (m²), or standard deviation (m) with VARIANCE_AS_STD.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: NUGGET, SILL, RANGE (NaN for linear/power), N_POINTS, VALID_CELLS, CV_ME, CV_RMSE, CV_MSE (NaN without cross-validation).&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;نوع الكريغينغ&lt;/b&gt; (KRIGING_TYPE، 0 عادي (الافتراضي)، 1 شامل بانجراف خطي).&lt;/li&gt;&lt;li&gt;&lt;b&gt;نموذج الفاريوغرام&lt;/b&gt; (VARIOGRAM، 0 خطي، 1 قوة (power)، 2 غاوسي، 3 كروي (الافتراضي)، 4 أُسّي).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الفاريوغرام&lt;/b&gt; (VARIOGRAM_NUGGET م²، VARIOGRAM_SILL م²، VARIOGRAM_RANGE م؛ الخطي: VARIOGRAM_SLOPE؛ القوة: VARIOGRAM_SCALE و VARIOGRAM_EXPONENT؛ كلها أرقام اختيارية). الفراغ = مُوفَّق تلقائياً. العتبة تشمل الأثر الكتلي؛ والمدى هو المدى العملي.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عدد الجيران&lt;/b&gt; (NEIGHBOURS، الافتراضي 16، ≥ 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;عدد النقاط لمواءمة الفاريوغرام&lt;/b&gt; (FIT_POINTS، الافتراضي 3000).&lt;/li&gt;&lt;li&gt;&lt;b&gt;عدد فئات مسافة الإزاحة&lt;/b&gt; (NLAGS، الافتراضي 12) و&lt;b&gt;أقصى مسافة إزاحة&lt;/b&gt; (MAX_LAG، م، الافتراضي 0 = تلقائي: ثلاثة أضعاف المسافة النموذجية إلى الجار رقم NEIGHBOURS، وهو المقياس الذي يستخدمه الكريغينغ المحلي، كي يُعايَن جيداً أثر الكتلة وشكل الفاريوغرام عند المسافات القصيرة، وهما ما يحدد الأوزان والتباين؛ وتصف العتبة والمدى المُوائَمان حينئذٍ ذلك المقياس المحلي). لمواءمة تقليدية على مقياس الحقل كله حدِّد مثلاً نصف النطاق (Journel &amp;amp; Huijbregts 1978). يُرفع أثر الكتلة المُوائَم إلى 1 % على الأقل من نصف التباين (semivariance) عند أقصى مسافة إزاحة، من أجل الاستقرار العددي (نموذجا غاوس والقوة).&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط التحقق المتقاطع&lt;/b&gt; (CV_POINTS، الافتراضي 0 = معطَّل): استبعاد فردي على هذا العدد من النقاط العشوائية؛ يعطي ME وRMSE ومتوسط الخطأ المعيَّر (المثالي 0) وقيمة RMS للخطأ المعيَّر (المثالي 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;البذرة العشوائية&lt;/b&gt; (SEED، الافتراضي 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مخرج التباين&lt;/b&gt; (OUTPUT_VARIANCE، GeoTIFF اختياري): تباين الكريغينغ (م²)، أو الانحراف المعياري (م) مع VARIANCE_AS_STD.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;أرقام المخرجات: NUGGET وSILL وRANGE (NaN للنموذجين الخطي والقوة)، وN_POINTS وVALID_CELLS وCV_ME وCV_RMSE وCV_MSE (NaN دون تحقق متقاطع).&lt;/p&gt;</translation>
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
    </context>
    <context>
        <name>LidarQaAlgorithm</name>
        <message>
            <source>Point density and quality (with parameter advice)</source>
            <translation>كثافة النقاط وجودتها (مع توصيات المعاملات)</translation>
        </message>
        <message>
            <source>Density rasters, gaps, duplicates and noise of a cloud, and the filter window and DTM cell its density supports.</source>
            <translation>شبكات الكثافة والفجوات والنقاط المكررة والضوضاء في سحابة، ونافذة المرشّح وخلية نموذج التضاريس التي تسمح بها كثافتها.</translation>
        </message>
        <message>
            <source>density,quality,qa,lasinfo,gaps,duplicates,noise,scan angle,returns,advice,lidar</source>
            <translation>كثافة,جودة,qa,lasinfo,فجوات,مكررات,ضوضاء,زاوية المسح,انعكاسات,توصيات,ليدار</translation>
        </message>
        <message>
            <source>&lt;p&gt;Checks a LAS/LAZ cloud before processing: density rasters of all returns, last returns and ground points, cells with returns but no ground (gaps), histograms of returns and classes, duplicate points, the share of noise (classes 7, 18) and the scan-angle range. It then states which settings the density supports: the ground filter window (1–2 pts/m² → 2 m), the DTM cell size, LOD1 only below 1 pt/m² (about 0.6 pts/m² in the ELiT study), and the radius and tile of our slope-based and LSQ filters.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz CELL_SIZE=5 OUTPUT=density.tif OUTPUT_HTML=qa.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las/.laz in a projected CRS (metres); a cloud in degrees is refused.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell size&lt;/b&gt; (CELL_SIZE, m, default 5, &amp;gt; 0): cell of the density rasters.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground classes&lt;/b&gt; (GROUND_CLASSES, default &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Density rasters&lt;/b&gt; (OUTPUT): GeoTIFF with four bands: all returns, last returns, ground (pts/m²), gap (1/0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): HTML report with maps and advice.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: DENSITY, GROUND_DENSITY (pts/m²), GAP_SHARE, DUPLICATES, NOISE_SHARE, GROUND_WINDOW (m), DTM_CELL (m).&lt;/p&gt;</source>
            <translation>&lt;p&gt;يفحص سحابة LAS/LAZ قبل المعالجة: شبكات كثافة كل الانعكاسات والانعكاسات الأخيرة ونقاط الأرض، والخلايا التي فيها انعكاسات بلا أرض (فجوات)، ومدرّجات الانعكاسات والأصناف، والنقاط المكررة، ونسبة الضوضاء (الصنفان 7 و18) ومدى زاوية المسح. ثم يبيّن الإعدادات التي تسمح بها الكثافة: نافذة مرشّح الأرض (1–2 نقطة/م² ← 2 م)، وحجم خلية نموذج التضاريس، وLOD1 فقط تحت نقطة واحدة/م² (نحو 0.6 نقطة/م² في دراسة ELiT)، ونصف قطر وبلاطة مرشّحينا المعتمدين على الميل وLSQ.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz CELL_SIZE=5 OUTPUT=density.tif OUTPUT_HTML=qa.html.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف ‎.las/.laz في نظام إسقاط مستوٍ (بالأمتار)؛ تُرفض السحابة بالدرجات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم الخلية&lt;/b&gt; (CELL_SIZE، م، الافتراضي 5، &amp;gt; 0): خلية شبكات الكثافة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;أصناف الأرض&lt;/b&gt; (GROUND_CLASSES، الافتراضي &lt;code&gt;2&lt;/code&gt;).&lt;/li&gt;&lt;li&gt;&lt;b&gt;شبكات الكثافة&lt;/b&gt; (OUTPUT): ملف GeoTIFF بأربع طبقات: كل الانعكاسات، الأخيرة، الأرض (نقطة/م²)، الفجوة (1/0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري): تقرير HTML بالخرائط والتوصيات.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;الأعداد الناتجة: DENSITY وGROUND_DENSITY (نقطة/م²) وGAP_SHARE وDUPLICATES وNOISE_SHARE وGROUND_WINDOW (م) وDTM_CELL (م).&lt;/p&gt;</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>&lt;p&gt;Classifies the ground of a LiDAR point cloud, interpolates a DTM from the ground points and measures its accuracy against check points, in one step. It writes all its outputs or none: when any step fails or is cancelled, no classified cloud, DTM or report is left behind.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz CHECKPOINTS_CSV=gnss.csv CELL_SIZE=1 OUTPUT=classified.laz OUTPUT_DTM=dtm.tif OUTPUT_HTML=accuracy.html → the classified cloud, the DTM and the RMSE.&lt;/p&gt;&lt;p&gt;The steps are the recommended ground filter (the improved least-squares filter where the recommended one is not installed), the IDW DTM (power 3, 12 neighbours by default: the seed paper's best setting) and the DTM accuracy; the results equal those of the three algorithms run one after another. Before anything is written the CRS, the check points (no duplicates, inside the cloud's extent) and every output path are checked. The graphical model of the same name is its editable counterpart, without this guarantee.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt;: .las or .laz in a projected CRS (metres).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (default yes), with its search cell (m, default 5) and depth (m, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;DTM cell size&lt;/b&gt; (m, default 1), &lt;b&gt;IDW power&lt;/b&gt; (default 3), &lt;b&gt;neighbours&lt;/b&gt; (default 12), &lt;b&gt;fill data gaps&lt;/b&gt; (default no) and a &lt;b&gt;CRS&lt;/b&gt; for a cloud without a CRS record.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Check points&lt;/b&gt;: a point layer (heights from a field or the geometry Z) or a CSV/TXT file (id, x, y, z) with its CRS; reprojection of x, y on request; bilinear (default) or nearest-cell sampling.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Outputs&lt;/b&gt;: classified cloud, DTM (GeoTIFF), check-point residuals and the DTM accuracy report; optional ground filter report and DTM report.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;يصنّف أرض سحابة نقاط LiDAR، ويستكمل منها نموذج تضاريس رقميًا (DTM) من نقاط الأرض، ويقيس دقته مقابل نقاط التحقق، في خطوة واحدة. يكتب كل نواتجه أو لا شيء منها: إذا فشلت أي خطوة أو أُلغيت لا تبقى سحابة مصنّفة ولا DTM ولا تقرير.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: &lt;span dir="ltr"&gt;INPUT=tile.laz CHECKPOINTS_CSV=gnss.csv CELL_SIZE=1 OUTPUT=classified.laz OUTPUT_DTM=dtm.tif OUTPUT_HTML=accuracy.html&lt;/span&gt; ← السحابة المصنّفة والـ DTM وقيمة RMSE.&lt;/p&gt;&lt;p&gt;الخطوات هي مرشّح الأرض الموصى به (أو مرشّح المربعات الصغرى المحسّن حيث لا يتوفر الموصى به)، ثم DTM بطريقة IDW (الأس 3 و12 جارًا افتراضيًا: أفضل إعداد في البحث المرجعي)، ثم دقة الـ DTM؛ والنتائج مطابقة لتشغيل الخوارزميات الثلاث واحدة تلو الأخرى. قبل كتابة أي شيء يُتحقَّق من نظام الإحداثيات ومن نقاط التحقق (بلا تكرار وضمن امتداد السحابة) ومن كل مسار ناتج. النموذج الرسومي الذي يحمل الاسم نفسه هو نظيره القابل للتعديل، ولكن دون هذا الضمان.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt;: ملف ‎.las‏ أو ‎.laz‏ في نظام إحداثيات مسقط (أمتار).&lt;/li&gt;&lt;li&gt;&lt;b&gt;إزالة النقاط الشاذة المنخفضة أولًا&lt;/b&gt; (افتراضيًا نعم)، مع خلية البحث (م، افتراضيًا 5) والعمق (م، افتراضيًا 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم خلية الـ DTM&lt;/b&gt; (م، افتراضيًا 1)، و&lt;b&gt;أس IDW&lt;/b&gt; (افتراضيًا 3)، و&lt;b&gt;عدد الجيران&lt;/b&gt; (افتراضيًا 12)، و&lt;b&gt;ملء فجوات البيانات&lt;/b&gt; (افتراضيًا لا)، و&lt;b&gt;نظام إحداثيات&lt;/b&gt; لسحابة بلا سجل نظام إحداثيات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط التحقق&lt;/b&gt;: طبقة نقطية (الارتفاعات من حقل أو من Z الهندسة) أو ملف CSV/TXT ‏(id, x, y, z) مع نظام إحداثياته؛ إعادة إسقاط x وy عند الطلب؛ اعتيان ثنائي الخطية (افتراضيًا) أو بأقرب خلية.&lt;/li&gt;&lt;li&gt;&lt;b&gt;النواتج&lt;/b&gt;: السحابة المصنّفة، والـ DTM ‏(GeoTIFF)، وبواقي نقاط التحقق، وتقرير دقة الـ DTM؛ واختياريًا تقرير مرشّح الأرض وتقرير الـ DTM.&lt;/li&gt;&lt;/ul&gt;</translation>
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
            <source>Check points (CSV/TXT file: id,x,y,z)</source>
            <translation>نقاط التحقق (ملف CSV/TXT: ‏id,x,y,z)</translation>
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
            <source>Classified point cloud</source>
            <translation>سحابة النقاط المصنَّفة</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>نموذج الارتفاعات الرقمي للأرض (DTM)</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>بواقي نقاط التحقق</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>تقرير دقة نموذج التضاريس الرقمي</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>تقرير مرشّح الأرض</translation>
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
            <translation>لم يجد مرشّح الأرض أي نقطة أرض؛ لا يمكن استكمال نموذج تضاريس. لم يُكتب أي ناتج.</translation>
        </message>
    </context>
    <context>
        <name>LsqGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (least-squares polynomial)</source>
            <translation>فلتر نقاط الأرض (متعدد حدود بالمربعات الصغرى)</translation>
        </message>
        <message>
            <source>lidar,ground,filter,bare earth,dtm,classification,least squares,polynomial,tiles,las,laz,isprs</source>
            <translation>ليدار,أرض,فلتر,الأرض العارية,dtm,تصنيف,المربعات الصغرى,متعدد الحدود,بلاطات,las,laz,isprs</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>&lt;p&gt;Separates bare-earth points from buildings and vegetation in an airborne LiDAR cloud by fitting least-squares polynomial surfaces per square tile (Damascus Univ. J. Eng. Sci. 29(2), 2013). In every tile the surface is fitted, points more than THRESHOLD above it are dropped, and the fit is repeated until the minimum, maximum, mean and standard deviation of the kept heights stop changing (TOLERANCE) or MAX_ITERATIONS; then every point with z ≤ ẑ + THRESHOLD is ground. Any classification already in the file is ignored and replaced.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Output classes&lt;/b&gt; (ASPRS): 2 ground, 1 other (buildings, vegetation), 7 low noise (pre-filter), 0 never classified (only with SPARSE_TILES = leave unclassified). Every other attribute of every point, the point format, scales, offsets, VLRs and CRS are copied unchanged.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz TILE_SIZE=50 THRESHOLD=0.5 ORDER=2 OUTPUT=classified.laz GROUND_OUTPUT=ground.laz OUTPUT_HTML=report.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz file, projected CRS in metres.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Order&lt;/b&gt; (ORDER, default 2): 1 = plane z = b0 + b1·x + b2·y; 2 = quadratic z = b0 + b1·x² + b2·y² + b3·xy + b4·x + b5·y (better on every sample of the paper).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Tile size&lt;/b&gt; (TILE_SIZE, m, default 50): larger than the largest building, so that every tile holds ground (paper: 100 m for large buildings, 50 m for small ones). Tiles are square, anchored at the minimum x, y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Threshold&lt;/b&gt; (THRESHOLD, m, default 0.5): 0.5–1.0 m, larger on steeper terrain.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mode&lt;/b&gt; (MODE, default Faithful): Faithful = the paper. Improved = ours, beyond the paper: coarse-to-fine tiles (2, 1, ½, ¼ × TILE_SIZE) fitted on overlapping windows, each level started from the previous level's ground, and a threshold that grows with the surface slope (by 2.5 m per unit gradient, at most 1 m). On the ISPRS samples it lowers the mean total error from 8.9 % (paper) to about 4.9 % with one parameter set; it costs about 15 times the time and twice the memory of the faithful mode (about 2 M points/s and 100 bytes per point in faithful mode).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, default yes): points far below their neighbours become class 7 and take no part in the fit (NOISE_RADIUS, m, default 5: neighbourhood cell; NOISE_THRESHOLD, m, default 1: depth below the neighbours).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Maximum iterations&lt;/b&gt; (MAX_ITERATIONS, default 5, the paper's tables) and &lt;b&gt;stop tolerance&lt;/b&gt; (TOLERANCE, m, default 0.01).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Random fitting subset per tile&lt;/b&gt; (SUBSET_SIZE, points, default 0 = all; the paper used 5000) and its &lt;b&gt;seed&lt;/b&gt; (SEED). All points are classified.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Minimum points per tile&lt;/b&gt; (MIN_POINTS, default 0 = 3 × the number of coefficients) and &lt;b&gt;under-populated tiles&lt;/b&gt; (SPARSE_TILES): borrow the nearest fitted tile's surface (default) or leave their points unclassified (class 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Rejection&lt;/b&gt; (REJECTION): re-weighted (default; a point dropped earlier may return when the surface moves) or cumulative (dropped for good).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Outputs&lt;/b&gt;: classified cloud (OUTPUT, .laz or .las), optional ground-only cloud (GROUND_OUTPUT), optional HTML report (OUTPUT_HTML) with the parameters, class counts, the per-iteration statistics of the paper's Tables 1–2, per-tile statistics, time and points per second; optional CSV of every tile's iterations and coefficients (TILE_STATS); numbers N_GROUND, N_OTHER, N_NOISE, N_UNCLASSIFIED, N_TILES, POINTS_PER_SECOND.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Measure the result against reference labels with &lt;i&gt;Ground filter accuracy&lt;/i&gt;. Nothing is written when the run fails or is cancelled.&lt;/p&gt;</source>
            <translation>&lt;p&gt;تفصل نقاط سطح الأرض العارية عن المباني والغطاء النباتي في سحابة ليدار جوية بمواءمة سطوح متعددة حدود بالمربعات الصغرى في كل بلاطة مربعة (مجلة جامعة دمشق للعلوم الهندسية 29(2)، 2013). في كل بلاطة يُوائَم السطح، وتُستبعد النقاط التي تعلوه بأكثر من THRESHOLD، وتُكرَّر المواءمة حتى تتوقف القيمة الدنيا والعليا والمتوسط والانحراف المعياري للارتفاعات المُبقاة عن التغيُّر (TOLERANCE) أو يُبلغ MAX_ITERATIONS؛ ثم تُعَدّ أرضاً كل نقطة تحقق z ≤ ẑ + THRESHOLD. يُتجاهَل أي تصنيف موجود في الملف ويُستبدل.&lt;/p&gt;&lt;p&gt;&lt;b&gt;أصناف المخرج&lt;/b&gt; (ASPRS): 2 أرض، 1 أخرى (مبانٍ، غطاء نباتي)، 7 ضوضاء منخفضة (الفلترة المسبقة)، 0 لم تُصنَّف قط (فقط مع SPARSE_TILES = ترك النقاط دون تصنيف). تُنسخ دون تغيير جميع الخصائص الأخرى لكل نقطة، وصيغة النقاط، ومعاملات المقياس والإزاحة، وسجلات VLR، ونظام الإحداثيات.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz TILE_SIZE=50 THRESHOLD=0.5 ORDER=2 OUTPUT=classified.laz GROUND_OUTPUT=ground.laz OUTPUT_HTML=report.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف .las أو .laz بنظام إحداثيات مُسقَط بالأمتار.&lt;/li&gt;&lt;li&gt;&lt;b&gt;الدرجة&lt;/b&gt; (ORDER، الافتراضي 2): 1 = مستوٍ z = b0 + b1·x + b2·y؛ 2 = سطح تربيعي z = b0 + b1·x² + b2·y² + b3·xy + b4·x + b5·y (أفضل في جميع عيّنات البحث).&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم البلاطة&lt;/b&gt; (TILE_SIZE، م، الافتراضي 50): أكبر من أكبر مبنى، كي تحوي كل بلاطة نقاطاً من الأرض (البحث: 100 م للمباني الكبيرة، 50 م للصغيرة). البلاطات مربعة، ومبدؤها عند أصغر x وy.&lt;/li&gt;&lt;li&gt;&lt;b&gt;العتبة&lt;/b&gt; (THRESHOLD، م، الافتراضي 0.5): 0.5–1.0 م، وأكبر في التضاريس الأشد انحداراً.&lt;/li&gt;&lt;li&gt;&lt;b&gt;النمط&lt;/b&gt; (MODE، الافتراضي: مطابق): مطابق = طريقة البحث. محسَّن = من إضافتنا، يتجاوز البحث: بلاطات من الخشن إلى الدقيق (2، 1، ½، ¼ × TILE_SIZE) تُوائَم على نوافذ متداخلة، ويبدأ كل مستوى من نقاط الأرض في المستوى السابق، مع عتبة تزداد بازدياد ميل السطح (بمقدار 2.5 م لكل وحدة تدرّج، وبحد أقصى 1 م). على عيّنات ISPRS يخفض متوسط الخطأ الكلي من 8.9 % (البحث) إلى نحو 4.9 % بمجموعة معاملات واحدة؛ ويستغرق نحو 15 ضعف زمن النمط المطابق وضعف ذاكرته (نحو 2 مليون نقطة/ث و100 بايت لكل نقطة في النمط المطابق).&lt;/li&gt;&lt;li&gt;&lt;b&gt;إزالة القيم الشاذة المنخفضة أولاً&lt;/b&gt; (NOISE، الافتراضي: نعم): النقاط الواقعة أسفل جيرانها بكثير تصبح من الصنف 7 ولا تشارك في المواءمة (NOISE_RADIUS، م، الافتراضي 5: خلية الجوار؛ NOISE_THRESHOLD، م، الافتراضي 1: العمق تحت الجيران).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الحد الأقصى للتكرارات&lt;/b&gt; (MAX_ITERATIONS، الافتراضي 5، كما في جداول البحث) و&lt;b&gt;سماحية التوقف&lt;/b&gt; (TOLERANCE، م، الافتراضي 0.01).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مجموعة جزئية عشوائية للمواءمة في كل بلاطة&lt;/b&gt; (SUBSET_SIZE، نقاط، الافتراضي 0 = الكل؛ استخدم البحث 5000) و&lt;b&gt;بذرتها العشوائية&lt;/b&gt; (SEED). تُصنَّف جميع النقاط.&lt;/li&gt;&lt;li&gt;&lt;b&gt;الحد الأدنى للنقاط في البلاطة&lt;/b&gt; (MIN_POINTS، الافتراضي 0 = 3 × عدد معاملات متعدد الحدود) و&lt;b&gt;البلاطات قليلة النقاط&lt;/b&gt; (SPARSE_TILES): استعارة سطح أقرب بلاطة مُوائَمة (الافتراضي) أو ترك نقاطها دون تصنيف (الصنف 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الاستبعاد&lt;/b&gt; (REJECTION): إعادة الترجيح (الافتراضي؛ قد تعود نقطة استُبعدت سابقاً عندما يتحرك السطح) أو تراكمي (تُستبعد النقطة نهائياً).&lt;/li&gt;&lt;li&gt;&lt;b&gt;المخرجات&lt;/b&gt;: السحابة المصنَّفة (OUTPUT، بالامتداد .laz أو .las)، وسحابة نقاط الأرض فقط اختيارياً (GROUND_OUTPUT)، وتقرير HTML اختياري (OUTPUT_HTML) فيه المعاملات وأعداد النقاط في كل صنف وإحصاءات كل تكرار كما في الجدولين 1–2 من البحث وإحصاءات كل بلاطة والزمن وعدد النقاط في الثانية؛ وملف CSV اختياري بتكرارات كل بلاطة ومعاملاتها (TILE_STATS)؛ والأرقام N_GROUND وN_OTHER وN_NOISE وN_UNCLASSIFIED وN_TILES وPOINTS_PER_SECOND.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;قِس النتيجة مقارنةً بالتصنيفات المرجعية باستخدام &lt;i&gt;دقة فلتر نقاط الأرض&lt;/i&gt;. لا يُكتب أي شيء إذا فشل التشغيل أو أُلغي.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Per-tile iteration statistics (CSV)</source>
            <translation>إحصاءات التكرارات لكل بلاطة (CSV)</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>ملفات CSV (*.csv)</translation>
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
            <source>&lt;p&gt;Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) by progressive TIN densification (Axelsson 2000): seeds are the lowest points of overlapping parcels larger than the largest building; the TIN is densified with every point close enough to its facet and seen under a small enough angle from its vertices, until no point is added. Pits and spikes are removed first by a step filter.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz MAX_BUILDING=50 for a town with 50 m buildings. On the 8 ISPRS samples its mean total error is 8.05 % at the defaults; use &lt;i&gt;Ground filter (recommended)&lt;/i&gt; unless you need a TIN filter.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz in a projected CRS (metres).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Cell&lt;/b&gt; (CELL, m, default 2): lowest point per cell for the step filter and the seeds.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Parcel size&lt;/b&gt; (MAX_BUILDING, m, default 30): larger than the largest building (30–50 m).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Distance to facet&lt;/b&gt; (MAX_DISTANCE, m, default 1.5) and &lt;b&gt;angle to vertices&lt;/b&gt; (MAX_ANGLE, degrees, default 18): densification limits.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Shortest facet edge&lt;/b&gt; (MIN_EDGE, m, default 1, advanced), &lt;b&gt;iteration cap&lt;/b&gt; (MAX_ITERATIONS, default 150, advanced).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Final distance&lt;/b&gt; (FINAL_DISTANCE, m, default 0.5): points this close to the final TIN are ground; &lt;b&gt;low-noise depth&lt;/b&gt; (LOW_NOISE_DEPTH, m, default 1.5): points deeper below it get class 7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Seed drop&lt;/b&gt; (SEED_DROP, %, default 0.3, advanced): lowest share of each parcel skipped before picking its seed.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Remove low outliers first&lt;/b&gt; (NOISE, default yes; NOISE_RADIUS m, 5; NOISE_THRESHOLD m, 1).&lt;/li&gt;</source>
            <translation>&lt;p&gt;يصنّف سحابة نقاط LAS/LAZ إلى أرض (الصنف 2) ونقاط أخرى (الصنف 1) وضجيج منخفض (الصنف 7) بالتكثيف التدريجي لشبكة TIN ‏(Axelsson 2000): البذور هي أدنى نقاط قطع متداخلة أكبر من أكبر مبنى؛ وتُكثَّف الشبكة بكل نقطة قريبة بما يكفي من وجهها وتُرى بزاوية صغيرة بما يكفي من رؤوسه، حتى لا تُضاف أي نقطة. تُزال الحفر والنتوءات أولاً بمرشح الدرجات.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=tile.laz OUTPUT=classified.laz MAX_BUILDING=50 لمدينة مبانيها 50 م. متوسط خطئه الكلي على عينات ISPRS الثماني 8.05 % بالقيم الافتراضية؛ استخدم &lt;i&gt;مرشح الأرض (الموصى به)&lt;/i&gt; ما لم تحتج إلى مرشح TIN.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ‎.las أو ‎.laz في نظام إحداثيات مسقط (أمتار).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الخلية&lt;/b&gt; (CELL، م، الافتراضي 2): أدنى نقطة لكل خلية لمرشح الدرجات والبذور.&lt;/li&gt;&lt;li&gt;&lt;b&gt;حجم القطعة&lt;/b&gt; (MAX_BUILDING، م، الافتراضي 30): أكبر من أكبر مبنى (30–50 م).&lt;/li&gt;&lt;li&gt;&lt;b&gt;المسافة إلى الوجه&lt;/b&gt; (MAX_DISTANCE، م، الافتراضي 1.5) و&lt;b&gt;الزاوية إلى الرؤوس&lt;/b&gt; (MAX_ANGLE، درجات، الافتراضي 18): حدود التكثيف.&lt;/li&gt;&lt;li&gt;&lt;b&gt;أقصر ضلع للوجه&lt;/b&gt; (MIN_EDGE، م، الافتراضي 1، متقدم)، &lt;b&gt;الحد الأقصى للتكرارات&lt;/b&gt; (MAX_ITERATIONS، الافتراضي 150، متقدم).&lt;/li&gt;&lt;li&gt;&lt;b&gt;المسافة النهائية&lt;/b&gt; (FINAL_DISTANCE، م، الافتراضي 0.5): النقاط بهذا القرب من الشبكة النهائية أرض؛ &lt;b&gt;عمق الضجيج المنخفض&lt;/b&gt; (LOW_NOISE_DEPTH، م، الافتراضي 1.5): النقاط الأعمق تحتها تأخذ الصنف 7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نسبة البذور المُسقطة&lt;/b&gt; (SEED_DROP، %، الافتراضي 0.3، متقدم): أدنى نسبة من كل قطعة تُتخطى قبل اختيار بذرتها.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إزالة النقاط الشاذة المنخفضة أولاً&lt;/b&gt; (NOISE، الافتراضي نعم؛ NOISE_RADIUS م، 5؛ NOISE_THRESHOLD م، 1).&lt;/li&gt;</translation>
        </message>
        <message>
            <source>&lt;p&gt;Reference: Axelsson, P. (2000). DEM generation from laser scanner data using adaptive TIN models. IAPRS XXXIII-B4, 110–117.&lt;/p&gt;</source>
            <translation>&lt;p&gt;المرجع: Axelsson, P. (2000). DEM generation from laser scanner data using adaptive TIN models. IAPRS XXXIII-B4, 110–117.&lt;/p&gt;</translation>
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
            <source>Seed drop (%)</source>
            <translation>نسبة البذور المُسقطة (%)</translation>
        </message>
        <message>
            <source>PTD: parcels {} m, distance {} m, angle {}°</source>
            <translation>PTD: قطع {} م، مسافة {} م، زاوية {}°</translation>
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
            <source>&lt;p&gt;Rectifies every image of a folder that has its QGIS Georeferencer &lt;i&gt;.points&lt;/i&gt; file next to it (scan.tif + scan.tif.points), with a fixed transformation or the one recommended for each image, and writes one summary table: image, transformation, RMS_T, check-point / leave-one-out RMS_T, verdict.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT_FOLDER=scans TRANSFORMATION=8 OUTPUT_FOLDER=rectified OUTPUT_CSV=summary.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Input folder&lt;/b&gt; (INPUT_FOLDER).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Transformation&lt;/b&gt; (TRANSFORMATION, default 8 = recommended per image; 0 polynomial of order ORDER, 1–3 polynomial 1–3, 4 linear, 5 Helmert, 6 projective, 7 thin-plate spline).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Polynomial order&lt;/b&gt; (ORDER, default 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Refine GCPs&lt;/b&gt; (REFINE, default off): drop GCPs over the C5 limit 5·GR.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GCP CRS&lt;/b&gt; (GCP_CRS): for .points files without a '#CRS:' line.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resampling&lt;/b&gt; (RESAMPLING, default 0 = nearest).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output folder&lt;/b&gt; (OUTPUT_FOLDER): image_rectified.tif per image, each written all-or-nothing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Summary&lt;/b&gt; (OUTPUT_CSV, OUTPUT_HTML): one row per image; an image that cannot be rectified gets its error in the table and the others go on.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;p&gt;يصحّح كل مرئية في المجلد يجاورها ملف &lt;i&gt;.points&lt;/i&gt; من Georeferencer في QGIS (scan.tif + scan.tif.points)، بتحويل ثابت أو بالتحويل الموصى به لكل مرئية، ويكتب جدول ملخص واحداً: المرئية، التحويل، RMS_T، RMS_T نقاط التحقق / ترك واحدة، الحكم.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT_FOLDER=scans TRANSFORMATION=8 OUTPUT_FOLDER=rectified OUTPUT_CSV=summary.csv&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;مجلد الإدخال&lt;/b&gt; (INPUT_FOLDER).&lt;/li&gt;&lt;li&gt;&lt;b&gt;التحويل&lt;/b&gt; (TRANSFORMATION، الافتراضي 8 = الموصى به لكل مرئية؛ 0 كثيرة حدود من الدرجة ORDER، 1–3 كثيرة حدود 1–3، 4 خطي، 5 هلمرت، 6 إسقاطي، 7 شريحة الصفيحة الرقيقة).&lt;/li&gt;&lt;li&gt;&lt;b&gt;درجة كثيرة الحدود&lt;/b&gt; (ORDER، الافتراضي 1).&lt;/li&gt;&lt;li&gt;&lt;b&gt;تنقيح النقاط&lt;/b&gt; (REFINE، الافتراضي معطّل): حذف النقاط فوق حدّ C5 أي 5·GR.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نظام إحداثيات النقاط&lt;/b&gt; (GCP_CRS): لملفات .points التي لا سطر '#CRS:' فيها.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إعادة المعاينة&lt;/b&gt; (RESAMPLING، الافتراضي 0 = الأقرب).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مجلد الإخراج&lt;/b&gt; (OUTPUT_FOLDER): ‏image_rectified.tif لكل مرئية، يُكتب كل منها كاملاً أو لا يُكتب.&lt;/li&gt;&lt;li&gt;&lt;b&gt;الملخص&lt;/b&gt; (OUTPUT_CSV، OUTPUT_HTML): سطر لكل مرئية؛ المرئية التي يتعذر تصحيحها يُسجَّل خطؤها في الجدول وتستمر البقية.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Folder of images with .points files</source>
            <translation>مجلد المرئيات مع ملفات .points</translation>
        </message>
        <message>
            <source>Transformation</source>
            <translation>التحويل</translation>
        </message>
        <message>
            <source>polynomial of order ORDER</source>
            <translation>كثيرة حدود من الدرجة ORDER</translation>
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
        <message>
            <source>CRS of the GCP map coordinates (if the file does not say)</source>
            <translation>نظام الإحداثيات للإحداثيات الخرائطية لنقاط الضبط (إن لم يحدده الملف)</translation>
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
            <source>Summary report</source>
            <translation>تقرير الملخص</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>Accuracy report</source>
            <translation>تقرير الدقة</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
        </message>
        <message>
            <source>OUTPUT must be a GeoTIFF file (.tif); got {0}.</source>
            <translation>يجب أن يكون OUTPUT ملف GeoTIFF (.tif)؛ القيمة المعطاة: {0}.</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Target CRS&lt;/b&gt; (TARGET_CRS, default the GCP CRS): output CRS; GDAL reprojects after the polynomial.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resampling&lt;/b&gt; (RESAMPLING, default 0 = nearest neighbour as in the paper): 0 near, 1 bilinear, 2 cubic, 3 cubic spline, 4 Lanczos, 5 average, 6 mode.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Output resolution&lt;/b&gt; (RESOLUTION, target-CRS units, default GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Nodata&lt;/b&gt; (NODATA, optional): value outside the image footprint (default: the input's nodata, else 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Rectified image&lt;/b&gt; (OUTPUT): GeoTIFF (written under a temporary name, renamed on success; nothing is left behind on failure).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): HTML accuracy report.&lt;/li&gt;&lt;/ul&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;نظام الإحداثيات الهدف&lt;/b&gt; (TARGET_CRS، الافتراضي نظام إحداثيات نقاط الضبط): نظام إحداثيات المخرج؛ يعيد GDAL الإسقاط بعد تطبيق متعدد الحدود.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إعادة الاعتيان&lt;/b&gt; (RESAMPLING، الافتراضي 0 = أقرب جار كما في البحث): 0 أقرب جار، 1 ثنائي الخطية، 2 تكعيبي، 3 شريحة تكعيبية (cubic spline)، 4 Lanczos، 5 المتوسط، 6 المنوال.&lt;/li&gt;&lt;li&gt;&lt;b&gt;دقة تمييز المخرج&lt;/b&gt; (RESOLUTION، بوحدات نظام الإحداثيات الهدف، الافتراضي GR).&lt;/li&gt;&lt;li&gt;&lt;b&gt;قيمة nodata&lt;/b&gt; (NODATA، اختياري): القيمة خارج حدود الصورة (الافتراضي: قيمة nodata في الإدخال، وإلا 0).&lt;/li&gt;&lt;li&gt;&lt;b&gt;الصورة المصحَّحة هندسياً&lt;/b&gt; (OUTPUT): GeoTIFF (يُكتب باسم مؤقت ثم يُعاد تسميته عند النجاح؛ ولا يبقى أي أثر عند الفشل).&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري): تقرير دقة بصيغة HTML.&lt;/li&gt;&lt;/ul&gt;</translation>
        </message>
        <message>
            <source>Rectify image with GCPs</source>
            <translation>تصحيح مرئية بنقاط الضبط الأرضي</translation>
        </message>
        <message>
            <source>&lt;p&gt;Rectifies (warps) an image with ground control points through GDAL: a polynomial of order 1–3, a linear, Helmert, projective or thin-plate-spline transformation, or the one with the lowest check-point / leave-one-out error (as &lt;i&gt;gdalwarp -order N&lt;/i&gt; / &lt;i&gt;-tps&lt;/i&gt;), and writes the accuracy report. The input image is never modified.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=scan.tif GCP_FILE=scan.tif.points TRANSFORMATION=8 REFINE=true OUTPUT=scan_rect.tif OUTPUT_HTML=scan_rect.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Image&lt;/b&gt; (INPUT): the raster to rectify.&lt;/li&gt;</source>
            <translation>&lt;p&gt;يصحّح (يعيد تشكيل) مرئية بنقاط الضبط الأرضي عبر GDAL: كثيرة حدود من الدرجة 1–3، أو تحويل خطي أو هلمرت أو إسقاطي أو شريحة الصفيحة الرقيقة، أو التحويل صاحب أصغر خطأ على نقاط التحقق / ترك واحدة (مثل &lt;i&gt;gdalwarp -order N&lt;/i&gt; / &lt;i&gt;-tps&lt;/i&gt;)، ويكتب تقرير الدقة. لا تُعدَّل المرئية المدخلة أبداً.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=scan.tif GCP_FILE=scan.tif.points TRANSFORMATION=8 REFINE=true OUTPUT=scan_rect.tif OUTPUT_HTML=scan_rect.html&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;المرئية&lt;/b&gt; (INPUT): الراستر المراد تصحيحه.&lt;/li&gt;</translation>
        </message>
    </context>
    <context>
        <name>SlopeGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (slope-based)</source>
            <translation>فلتر نقاط الأرض (على أساس الميل)</translation>
        </message>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,vosselman,slope,point cloud</source>
            <translation>ليدار,las,laz,أرض,فلتر,تصنيف,dtm,الأرض العارية,vosselman,الميل,سحابة النقاط</translation>
        </message>
        <message>
            <source>&lt;p&gt;Classifies a LAS/LAZ point cloud into ground (class 2) and non-ground (class 1) with Vosselman's (2000) slope-based filter: a point is non-ground when some neighbour at horizontal distance 0 &amp;lt; d ≤ r lies more than d·tan θ + h below it. Single pass, neighbours from the whole cloud, exact (labels identical to a brute-force check of every pair) and fast (about a million points per second on one core at r = 3 m). Low outliers get class 7; every other attribute is copied unchanged. The input classification is ignored.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: the forest study's setting RADIUS=3 SLOPE=44 HEIGHT_TOLERANCE=0 allows a rise of 2.90 m at 3 m. Tune r and θ to your data with &lt;i&gt;Slope filter threshold sweep&lt;/i&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): .las or .laz file in a projected CRS (metres).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Radius r&lt;/b&gt; (RADIUS, m, default 10, &amp;gt; 0): neighbourhood radius. An object is removed only within r of its edge, so r must exceed half the width of the largest building to remove; larger r costs more time.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Slope threshold θ&lt;/b&gt; (SLOPE, degrees, default 40, strictly between 0 and 90): the steepest terrain kept. Allowed rise at 3 m: 2.52 m (40°), 2.90 m (44°), 3.33 m (48°), 3.84 m (52°), 4.45 m (56°), 5.20 m (60°).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Height tolerance h&lt;/b&gt; (HEIGHT_TOLERANCE, m, default 0.2, ≥ 0): extra rise allowed for every pair, absorbs ranging noise between close points; 0 is the rule as published.&lt;/li&gt;</source>
            <translation>&lt;p&gt;تصنِّف سحابة نقاط LAS/LAZ إلى أرض (الصنف 2) وغير أرض (الصنف 1) بفلتر الميل الذي اقترحه Vosselman (2000): تُعَدّ النقطة غير أرضية إذا وُجدت نقطة مجاورة على مسافة أفقية 0 &lt; d ≤ r تقع أسفلها بأكثر من d·tan θ + h. مرور واحد، والجيران من السحابة كلها، ودقيق (التصنيفات مطابقة لفحص شامل لكل الأزواج) وسريع (نحو مليون نقطة في الثانية على نواة معالج واحدة عند r = 3 م). تأخذ القيم الشاذة المنخفضة الصنف 7؛ وتُنسخ سائر الخصائص دون تغيير. يُتجاهَل تصنيف الإدخال.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: إعداد دراسة الغابات RADIUS=3 SLOPE=44 HEIGHT_TOLERANCE=0 يسمح بفرق ارتفاع 2.90 م على مسافة 3 م. اضبط r وθ لبياناتك باستخدام &lt;i&gt;مسح عتبات فلتر الميل&lt;/i&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): ملف .las أو .laz بنظام إحداثيات مُسقَط (بالأمتار).&lt;/li&gt;&lt;li&gt;&lt;b&gt;نصف القطر r&lt;/b&gt; (RADIUS، م، الافتراضي 10، &gt; 0): نصف قطر الجوار. لا يُزال الجسم إلا ضمن مسافة r من حافته، لذا يجب أن يتجاوز r نصف عرض أكبر مبنى يُراد إزالته؛ وكلما كبر r زاد الزمن.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عتبة الميل θ&lt;/b&gt; (SLOPE، درجات، الافتراضي 40، بين 0 و90 حصراً): أشد انحدار للتضاريس يُحتفظ به. فرق الارتفاع المسموح على مسافة 3 م: 2.52 م (40°)، 2.90 م (44°)، 3.33 م (48°)، 3.84 م (52°)، 4.45 م (56°)، 5.20 م (60°).&lt;/li&gt;&lt;li&gt;&lt;b&gt;سماحية الارتفاع h&lt;/b&gt; (HEIGHT_TOLERANCE، م، الافتراضي 0.2، ≥ 0): فرق ارتفاع إضافي مسموح لكل زوج، يمتص ضوضاء قياس المسافة بين النقاط المتقاربة؛ والقيمة 0 هي القاعدة كما نُشرت.&lt;/li&gt;</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <translation>سرعة الفلترة (نقطة/ث)</translation>
        </message>
        <message>
            <source>Slope filter: r = {} m, θ = {}°, h = {} m, {} returns, mode {}</source>
            <translation>فلتر الميل: r = {} م، θ = {}°، h = {} م، الارتدادات: {}، النمط: {}</translation>
        </message>
        <message>
            <source>{} points: {} ground, {} non-ground, {} low outliers; filter {:.1f} s</source>
            <translation>{} نقطة: {} أرضية، {} غير أرضية، {} قيم شاذة منخفضة؛ الفلترة {:.1f} ث</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Keep existing noise classes&lt;/b&gt; (KEEP_NOISE, default yes, advanced): points already classified 7 or 18 keep their class and take no part.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classified point cloud&lt;/b&gt; (OUTPUT, .laz/.las): every point, classes 2/1/7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground points&lt;/b&gt; (GROUND_OUTPUT, optional): only the ground points.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML, optional): counts, settings, allowed-rise table, speed.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: N_POINTS, N_GROUND, N_NONGROUND, N_NOISE, POINTS_PER_SECOND (filter step only).&lt;/p&gt;&lt;p&gt;Reference: Vosselman, G. (2000). Slope based filtering of laser altimetry data. IAPRS XXXIII-B3, 935–942.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;الإبقاء على أصناف الضوضاء الموجودة&lt;/b&gt; (KEEP_NOISE، الافتراضي: نعم، خيار متقدم): النقاط المصنَّفة مسبقاً 7 أو 18 تحتفظ بصنفها ولا تشارك في الفلترة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط المصنَّفة&lt;/b&gt; (OUTPUT، .laz/.las): كل النقاط، بالأصناف 2/1/7.&lt;/li&gt;&lt;li&gt;&lt;b&gt;نقاط الأرض&lt;/b&gt; (GROUND_OUTPUT، اختياري): نقاط الأرض فقط.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML، اختياري): الأعداد والإعدادات وجدول فرق الارتفاع المسموح والسرعة.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;أرقام المخرجات: N_POINTS وN_GROUND وN_NONGROUND وN_NOISE وPOINTS_PER_SECOND (لخطوة الفلترة وحدها).&lt;/p&gt;&lt;p&gt;المرجع: Vosselman, G. (2000). Slope based filtering of laser altimetry data. IAPRS XXXIII-B3, 935–942.&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>SlopeThresholdSweepAlgorithm</name>
        <message>
            <source>Slope filter threshold sweep</source>
            <translation>مسح عتبات فلتر الميل</translation>
        </message>
        <message>
            <source>lidar,ground,filter,vosselman,slope,threshold,tuning,accuracy,type I,type II,kappa,isprs</source>
            <translation>ليدار,أرض,فلتر,vosselman,الميل,العتبة,المعايرة,الدقة,النوع الأول,النوع الثاني,كابا,isprs</translation>
        </message>
        <message>
            <source>&lt;p&gt;Runs the slope-based ground filter for every combination of slope thresholds θ, radii r and height tolerances h and reports, against reference labels, Type I error (ground rejected), Type II error (objects accepted as ground — the forest study's "error" column, which alone always favours low θ), total error and Cohen's kappa (Sithole &amp;amp; Vosselman 2004), then picks the best setting. One exact neighbourhood pass per radius and tolerance: every threshold then costs a single comparison per point.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: the forest study: SLOPES=40:60:4 RADII=3 HEIGHT_TOLERANCES=0. ISPRS reference samples: INPUT=samp31.laz (its own classification is the reference).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Point cloud&lt;/b&gt; (INPUT): LAS/LAZ. Its classification is never used to filter.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Reference cloud&lt;/b&gt; (REFERENCE, optional): a labelled copy of the same points in the same order; empty = the input's own classification (e.g. the ISPRS samples).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ground classes&lt;/b&gt; (GROUND_CLASSES, default "2"): reference classes counted as ground; all others are objects.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Slope thresholds&lt;/b&gt; (SLOPES, degrees, default "30,35,40,44,48,52,56,60"): a list or start:stop:step.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Radii&lt;/b&gt; (RADII, m, default "10") and &lt;b&gt;height tolerances&lt;/b&gt; (HEIGHT_TOLERANCES, m, default "0.2"): lists; each value is one pass.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Best by&lt;/b&gt; (METRIC, default 0): 0 lowest total error, 1 highest kappa, 2 lowest Type I, 3 lowest Type II.&lt;/li&gt;</source>
            <translation>&lt;p&gt;تشغِّل فلتر الأرض القائم على الميل لكل توليفة من عتبات الميل θ وأنصاف الأقطار r وسماحيات الارتفاع h، وتحسب مقارنةً بالتصنيفات المرجعية خطأ النوع الأول (رفض نقاط الأرض)، وخطأ النوع الثاني (قبول الأجسام كأرض — وهو عمود "الخطأ" في دراسة الغابات، الذي يرجِّح وحده دائماً قيم θ المنخفضة)، والخطأ الكلي، ومعامل كابا لكوهين (Sithole &amp; Vosselman 2004)، ثم تختار أفضل إعداد. مرور دقيق واحد على الجوار لكل نصف قطر وسماحية: بعدها لا تكلِّف كل عتبة سوى مقارنة واحدة لكل نقطة.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: دراسة الغابات: SLOPES=40:60:4 RADII=3 HEIGHT_TOLERANCES=0. عيّنات ISPRS المرجعية: INPUT=samp31.laz (تصنيفها نفسه هو المرجع).&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;سحابة النقاط&lt;/b&gt; (INPUT): LAS/LAZ. لا يُستخدم تصنيفها في الفلترة أبداً.&lt;/li&gt;&lt;li&gt;&lt;b&gt;السحابة المرجعية&lt;/b&gt; (REFERENCE، اختياري): نسخة مصنَّفة من النقاط نفسها وبالترتيب نفسه؛ فارغ = تصنيف سحابة الإدخال نفسها (مثل عيّنات ISPRS).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أصناف الأرض&lt;/b&gt; (GROUND_CLASSES، الافتراضي "2"): الأصناف المرجعية التي تُعَدّ أرضاً؛ وكل ما عداها أجسام.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عتبات الميل&lt;/b&gt; (SLOPES، درجات، الافتراضي "30,35,40,44,48,52,56,60"): قائمة أو start:stop:step (بداية:نهاية:خطوة).&lt;/li&gt;&lt;li&gt;&lt;b&gt;أنصاف الأقطار&lt;/b&gt; (RADII، م، الافتراضي "10") و&lt;b&gt;سماحيات الارتفاع&lt;/b&gt; (HEIGHT_TOLERANCES، م، الافتراضي "0.2"): قوائم؛ كل قيمة تعني مروراً واحداً.&lt;/li&gt;&lt;li&gt;&lt;b&gt;معيار الأفضلية&lt;/b&gt; (METRIC، الافتراضي 0): 0 أدنى خطأ كلي، 1 أعلى كابا، 2 أدنى خطأ من النوع الأول، 3 أدنى خطأ من النوع الثاني.&lt;/li&gt;</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <source>&lt;li&gt;&lt;b&gt;Sweep table&lt;/b&gt; (OUTPUT_CSV): one row per setting: radius_m, slope_deg, height_tolerance_m, allowed_rise_at_r_m, n_ground, a, b, c, d, type1_pct, type2_pct, total_pct, kappa_pct.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML): the table, the best setting and a chart of the errors against θ.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Classified with the best setting&lt;/b&gt; (OUTPUT, optional LAS/LAZ).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Output numbers: BEST_RADIUS, BEST_SLOPE, BEST_HEIGHT_TOLERANCE, BEST_TYPE1, BEST_TYPE2, BEST_TOTAL, BEST_KAPPA (percent), N_SETTINGS.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;جدول المسح&lt;/b&gt; (OUTPUT_CSV): صف لكل إعداد: radius_m, slope_deg, height_tolerance_m, allowed_rise_at_r_m, n_ground, a, b, c, d, type1_pct, type2_pct, total_pct, kappa_pct.&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML): الجدول وأفضل إعداد ومخطط للأخطاء مقابل θ.&lt;/li&gt;&lt;li&gt;&lt;b&gt;السحابة المصنَّفة بأفضل إعداد&lt;/b&gt; (OUTPUT، LAS/LAZ اختياري).&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;أرقام المخرجات: BEST_RADIUS وBEST_SLOPE وBEST_HEIGHT_TOLERANCE وBEST_TYPE1 وBEST_TYPE2 وBEST_TOTAL وBEST_KAPPA (بالنسبة المئوية) وN_SETTINGS.&lt;/p&gt;</translation>
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
            <source>&lt;p&gt;Triangulates the ground points of a LAS/LAZ file (Delaunay, Qhull) and gives every cell centre the height of the plane of its triangle — the TIN DTM most practitioners default to, the method of &lt;code&gt;gdal_grid -a linear&lt;/code&gt;. Triangles with an edge longer than the maximum edge are dropped, so gaps under buildings or water stay nodata unless you fill them; cells outside the points' convex hull are always nodata.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=0.5 MAX_EDGE=0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</source>
            <translation>&lt;p&gt;يثلّث نقاط الأرض في ملف LAS/LAZ (ديلوني، Qhull) ويعطي كل مركز خلية ارتفاع مستوى مثلثه — نموذج TIN للتضاريس الذي يعتمده معظم الممارسين، وهي طريقة &lt;code&gt;gdal_grid -a linear&lt;/code&gt;. تُحذف المثلثات التي يتجاوز أحد أضلاعها الطول الأقصى، فتبقى الفجوات تحت المباني أو فوق الماء بلا بيانات ما لم تطلب ملأها؛ والخلايا خارج الغلاف المحدّب للنقاط تبقى دائماً بلا بيانات.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt;: INPUT=ground.laz CLASSES=2 CELL_SIZE=0.5 MAX_EDGE=0.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;</translation>
        </message>
        <message>
            <source>&lt;li&gt;&lt;b&gt;Maximum triangle edge&lt;/b&gt; (MAX_EDGE, m, default 0 = automatic: ten mean point spacings, at least four cells): longer triangles are nodata.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Fill gaps&lt;/b&gt; (FILL_GAPS, default no): keep every triangle, bridging gaps inside the hull with flat facets.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Outputs also the numbers N_POINTS, N_TRIANGLES, VALID_CELLS, NODATA_CELLS.&lt;/p&gt;</source>
            <translation>&lt;li&gt;&lt;b&gt;أقصى طول لضلع المثلث&lt;/b&gt; (MAX_EDGE، م، الافتراضي 0 = تلقائي: عشرة أضعاف متوسط التباعد بين النقاط، وأربع خلايا على الأقل): المثلثات الأطول تُترك بلا بيانات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ملء الفجوات&lt;/b&gt; (FILL_GAPS، الافتراضي لا): إبقاء كل المثلثات وسدّ الفجوات داخل الغلاف بأوجه مستوية.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;يُخرج أيضاً الأعداد N_POINTS وN_TRIANGLES وVALID_CELLS وNODATA_CELLS.&lt;/p&gt;</translation>
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
            <source>CRS of the GCP map coordinates (if the file does not say)</source>
            <translation>نظام الإحداثيات للإحداثيات الخرائطية لنقاط الضبط (إن لم يحدده الملف)</translation>
        </message>
        <message>
            <source>Polynomial order (1–3)</source>
            <translation>درجة متعدد الحدود (1–3)</translation>
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
            <source>Transformation</source>
            <translation>التحويل</translation>
        </message>
        <message>
            <source>polynomial of order ORDER</source>
            <translation>كثيرة حدود من الدرجة ORDER</translation>
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
            <source>Refine GCPs: drop the worst while over the tolerance</source>
            <translation>تنقيح النقاط: حذف الأسوأ ما دام فوق التسامح</translation>
        </message>
        <message>
            <source>Refinement tolerance (map units) [default: C5 limit 5·GR]</source>
            <translation>تسامح التنقيح (وحدات الخريطة) [الافتراضي: حدّ C5 أي 5·GR]</translation>
        </message>
        <message>
            <source>Minimum GCPs kept by the refinement [default: minimum + 2]</source>
            <translation>أدنى عدد نقاط يبقيه التنقيح [الافتراضي: الحدّ الأدنى + 2]</translation>
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
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>سحابة النقاط لا تحوي سجل نظام إحداثيات ولم يُحدَّد نظام إحداثيات؛ اضبط المعامل CRS (مثلاً EPSG:32632). لم تُكتب أي مخرجات.</translation>
        </message>
        <message>
            <source>Cell size must be &gt; 0 (metres); give e.g. 1.0. No output was written.</source>
            <translation>يجب أن يكون حجم الخلية &gt; 0 (بالأمتار)؛ أدخل مثلاً 1.0. لم تُكتب أي مخرجات.</translation>
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
            <source>Report</source>
            <translation>التقرير</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>ملفات HTML (*.html)</translation>
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
            <translation>سرعة الفلترة (نقطة/ث)</translation>
        </message>
        <message>
            <source>{} points: {} ground, {} non-ground, {} low outliers; filter {:.1f} s</source>
            <translation>{} نقطة: {} أرضية، {} غير أرضية، {} قيم شاذة منخفضة؛ الفلترة {:.1f} ث</translation>
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
            <translation>الارتدادات المفلترة</translation>
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
            <translation>يجب أن تكون قيمتا NOISE_RADIUS وNOISE_THRESHOLD &gt; 0 م (مثلاً 5 و1)، أو أوقف الفلترة المسبقة NOISE.</translation>
        </message>
    </context>
</TS>
